// Break placement and aim, verified in the physics.
#include "client/bot/ai/break_shot.h"

#include <array>
#include <cmath>
#include <limits>

#include "client/bot/ai/cue_placement.h"
#include "client/bot/ai/safety_shot.h"

namespace pool::bot {
namespace {

// Lateral cue-ball positions to try, m.
constexpr std::array<double, 5> kBreakY{0.0, 0.12, -0.12, 0.24, -0.24};
// How far behind the head string the cue ball sits (the rules want it strictly behind), m.
constexpr double kSetback = 0.01;

// The object ball nearest the foot spot: the apex of the rack.
Vec2 apexBall(const PlanContext& context) {
  const Vec2 foot = context.view.context.spots.foot_spot;
  Vec2 apex = foot;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& b : context.balls) {
    if (b.id == physics::kCueBall || !physics::onTable(b.state)) continue;
    const double d = (b.pos.head<2>() - foot).norm();
    if (d < best) {
      best = d;
      apex = b.pos.head<2>();
    }
  }
  return apex;
}

double breakValue(const Trial& trial) {
  if (!trial.judged || trial.loses || trial.dead_layout) return -1.0;
  double value = trial.verdict.legal() ? 50.0 : 0.0;
  value += 10.0 * static_cast<double>(trial.verdict.pocketed.size());
  if (trial.verdict.turn_continues) value += 30.0;
  return value;
}

}  // namespace

PlannedShot planBreak(PlanContext& context) {
  const Vec2 apex = apexBall(context);
  std::optional<PlannedShot> best;
  for (double y : kBreakY) {
    const Vec2 at(context.view.headStringX() - kSetback, y);
    if (!placementLegal(context, at)) continue;
    PlannedShot shot = context.blank(ShotKind::Break);
    shot.cue_ball_at = at;
    shot.cue = stroke(std::atan2(apex.y() - at.y(), apex.x() - at.x()), kBreakSpeed, -0.1);
    const auto trial = context.tryShot(shot);
    shot.value = trial ? breakValue(*trial) : -1.0;
    if (!best || shot.value > best->value) best = shot;
    if (!trial) break;
  }
  if (best) return *best;
  const auto spots = restingSpots(context);
  return fallbackShot(context, spots.empty() ? std::nullopt : std::optional<Vec2>(spots.front()));
}

}  // namespace pool::bot
