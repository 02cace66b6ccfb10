// The cue's stroke after a release, and the aims it is drawn from.
#include "client/ui/window_stroke.h"

#include <algorithm>
#include <cmath>

#include "client/ui/aim_screenshot.h"
#include "protocol/command_limits.h"

namespace pool::ui {

std::pair<app::AimState, Eigen::Vector3d> releasedAim(const protocol::ShotRequest& shot,
                                                      const Eigen::Vector3d& cue_ball,
                                                      const game::LoadedTable& table) {
  app::AimState aim;
  aim.yaw = shot.cue.yaw;
  aim.tip_side = shot.cue.tip_side;
  aim.tip_height = shot.cue.tip_height;
  aim.elevation = shot.cue.elevation;
  const double max_speed = protocol::CommandLimits().max_speed;  // the same on every table
  aim.power = (shot.cue.speed - app::kMinCueSpeed) / (max_speed - app::kMinCueSpeed);
  aim.power = std::clamp(aim.power, 0.0, 1.0);
  Eigen::Vector3d ball = cue_ball;
  if (shot.cue_ball_at) ball = {shot.cue_ball_at->x(), shot.cue_ball_at->y(), table.radius()};
  return {aim, ball};
}

render::CueAim followedCue(const app::FollowedAim& followed, const game::LoadedTable& table) {
  const Eigen::Vector3d ball(followed.cue_ball.x(), followed.cue_ball.y(), table.radius());
  return cueAimOf(followed.aim, ball);
}

std::optional<render::CueAim> CueStroke::at(double now) {
  if (!stroke_) return std::nullopt;
  const float power =
      render::strokePower(stroke_->aim.power, static_cast<float>(now - stroke_->start));
  if (std::isnan(power)) {
    stroke_.reset();
    return std::nullopt;
  }
  render::CueAim aim = stroke_->aim;
  aim.power = power;
  return aim;
}

}  // namespace pool::ui
