// Aim limits and the command of an aim.
#include "client/app/aim.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pool::app {

void clampAim(AimState& aim, const protocol::CommandLimits& limits) {
  aim.yaw = std::remainder(aim.yaw, 2 * std::numbers::pi);
  if (aim.yaw <= -std::numbers::pi) aim.yaw += 2 * std::numbers::pi;
  // Just inside the circle: the server compares hypot() with the limit itself.
  const double reach = limits.miscue_limit * (1 - 1e-9);
  const double offset = std::hypot(aim.tip_side, aim.tip_height);
  if (offset > reach) {
    aim.tip_side *= reach / offset;
    aim.tip_height *= reach / offset;
  }
  aim.elevation = std::clamp(aim.elevation, 0.0, limits.max_elevation);
  aim.power = std::clamp(aim.power, 0.0, 1.0);
}

double cueSpeedOf(double power, const protocol::CommandLimits& limits) {
  return kMinCueSpeed + std::clamp(power, 0.0, 1.0) * (limits.max_speed - kMinCueSpeed);
}

double powerOfSpeed(double speed, const protocol::CommandLimits& limits) {
  return std::clamp((speed - kMinCueSpeed) / (limits.max_speed - kMinCueSpeed), 0.0, 1.0);
}

protocol::ShotRequest requestOf(const AimState& aim, const protocol::CommandLimits& limits) {
  AimState clamped = aim;
  clampAim(clamped, limits);
  protocol::ShotRequest request;
  request.cue.yaw = clamped.yaw;
  request.cue.tip_side = clamped.tip_side;
  request.cue.tip_height = clamped.tip_height;
  request.cue.elevation = clamped.elevation;
  request.cue.speed = cueSpeedOf(clamped.power, limits);
  request.cue.speed_is_ball = false;
  request.safety = clamped.call.safety;
  // A ball and its pocket; a ball alone is snooker's nominated ball (no pocket to call).
  if (!clamped.call.safety && clamped.call.ball) {
    request.called_ball = clamped.call.ball;
    request.called_pocket = clamped.call.pocket;
  }
  request.cue_ball_at = clamped.cue_ball_at;
  request.option = clamped.option;
  return request;
}

}  // namespace pool::app
