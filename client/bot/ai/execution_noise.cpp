// Gaussian execution noise on a stroke.
#include "client/bot/ai/execution_noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pool::bot {

ExecutionNoise olympiadNoise(double ball_radius) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  return {0.125 * kDegree, 0.1 * kDegree, 0.075, 0.5e-3 / ball_radius};
}

physics::CueShot perturbed(const physics::CueShot& shot, const ExecutionNoise& noise, Rng& rng) {
  physics::CueShot out = shot;
  // Every parameter draws every time, so the sequence does not depend on the noise.
  out.yaw += noise.yaw * rng.gaussian();
  out.elevation = std::max(0.0, out.elevation + noise.elevation * rng.gaussian());
  out.speed = std::max(0.0, out.speed + noise.speed * rng.gaussian());
  out.tip_side += noise.tip * rng.gaussian();
  out.tip_height += noise.tip * rng.gaussian();
  // A tip pushed past the miscue limit lands on its edge: the stroke stays one the server takes
  // (beyond it the command is refused as malformed and the turn waits on a resend).
  const double offset = std::hypot(out.tip_side, out.tip_height);
  constexpr double kEdge = physics::kMiscueLimit * (1.0 - 1e-9);
  if (offset > kEdge) {
    out.tip_side *= kEdge / offset;
    out.tip_height *= kEdge / offset;
  }
  return out;
}

}  // namespace pool::bot
