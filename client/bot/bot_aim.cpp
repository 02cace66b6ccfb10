// The bot's thinking cue: a swing onto the heading, then the draw-back.
#include "client/bot/bot_aim.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "protocol/command_limits.h"

namespace pool::bot {
namespace {

constexpr double kSwing = 0.35;    ///< rad the swing starts left of the planned heading
constexpr double kSwingEnd = 0.7;  ///< share of the think time the swing takes
constexpr double kMinSpeed = 0.3;  ///< m/s of an empty power bar (the window's)

double wrapped(double yaw) {
  double y = std::remainder(yaw, 2.0 * std::numbers::pi);
  if (y <= -std::numbers::pi) y += 2.0 * std::numbers::pi;
  return y;
}

}  // namespace

double powerOf(const PlannedShot& shot) {
  const double max_speed = protocol::CommandLimits{}.max_speed;
  return std::clamp((shot.cue.speed - kMinSpeed) / (max_speed - kMinSpeed), 0.0, 1.0);
}

protocol::AimSample thinkingAim(const PlannedShot& shot, const std::vector<physics::Ball>& balls,
                                double progress) {
  const double p = std::clamp(progress, 0.0, 1.0);
  const double swing = std::min(p / kSwingEnd, 1.0);
  const double eased = swing * swing * (3.0 - 2.0 * swing);
  protocol::AimSample aim;
  aim.yaw = wrapped(shot.cue.yaw + kSwing * (1.0 - eased));
  aim.tip_side = shot.cue.tip_side;
  aim.tip_height = shot.cue.tip_height;
  aim.elevation = shot.cue.elevation;
  aim.power = p <= kSwingEnd ? 0.0 : powerOf(shot) * (p - kSwingEnd) / (1.0 - kSwingEnd);
  for (const auto& b : balls) {
    if (b.id != shot.cue.ball || !physics::onTable(b.state)) continue;  // the ball struck
    aim.cue_ball_x = b.pos.x();
    aim.cue_ball_y = b.pos.y();
  }
  if (shot.cue_ball_at) {
    aim.cue_ball_x = shot.cue_ball_at->x();
    aim.cue_ball_y = shot.cue_ball_at->y();
  }
  return aim;
}

}  // namespace pool::bot
