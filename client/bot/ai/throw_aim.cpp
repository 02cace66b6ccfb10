// One physics probe per stroke, one Newton step on the cue's heading.
#include "client/bot/ai/throw_aim.h"

#include <algorithm>
#include <cmath>

namespace pool::bot {
namespace {

// How long the probe runs: twice the cue ball's time to contact at its starting speed, and a
// margin for a slow stroke (a probe that ends before the strike leaves the line alone).
double probeHorizon(const PotLine& line, double speed) {
  constexpr double kMargin = 0.3;   // s
  constexpr double kLongest = 6.0;  // s
  return std::min(kLongest, 2.0 * line.cue_distance / std::max(speed, 0.1) + kMargin);
}

}  // namespace

void aimForThrow(PlanContext& context, PlannedShot& shot, const PotLine& line) {
  const auto left = context.probeHeading(shot, line.ball, probeHorizon(line, shot.cue.speed));
  if (!left) return;
  const double r = context.view.radius();
  const double wanted = angleOf(line.object - line.ghost);
  const double error = angleBetween(angleOf(*left), wanted);
  // The geometry's rate of turn of the object ball's line per radian of cue heading.
  constexpr double kStep = 1e-4;  // rad
  const auto plus = contactLine(line.cue, line.object, shot.cue.yaw + kStep, r);
  const auto minus = contactLine(line.cue, line.object, shot.cue.yaw - kStep, r);
  if (!plus || !minus) return;
  const double rate = angleBetween(angleOf(*plus), angleOf(*minus)) / (2.0 * kStep);
  if (std::abs(rate) < 1e-6) return;
  // Throw is a few degrees; a larger error is no throw (a kiss, a miscue): leave the line alone.
  constexpr double kLargestCorrection = 0.1;  // rad of the object ball's line
  if (std::abs(error) > kLargestCorrection) return;
  shot.cue.yaw -= error / rate;
}

}  // namespace pool::bot
