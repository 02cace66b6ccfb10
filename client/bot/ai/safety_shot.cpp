// Verified safeties and the fallback hit.
#include "client/bot/ai/safety_shot.h"

#include <array>
#include <cmath>
#include <limits>

namespace pool::bot {
namespace {

constexpr std::array<double, 3> kSafetySpeeds{1.2, 2.0, 3.2};  // m/s, ball speed
// Contact offsets: full, and half-ball either side (fraction of 2R off the centre line).
constexpr std::array<double, 3> kContact{0.0, 0.5, -0.5};
constexpr double kFallbackSpeed = 2.5;                  // m/s
constexpr std::array<double, 2> kKickSpeeds{2.5, 4.0};  // m/s, ball speed

// Heading from `from` that makes the cue ball meet the ball at `object` with the given offset.
double aimWithOffset(const Vec2& from, const Vec2& object, double offset, double radius) {
  const Vec2 d = (object - from).normalized();
  const Vec2 side(-d.y(), d.x());
  const Vec2 aim = object + side * (offset * 2 * radius) - from;
  return std::atan2(aim.y(), aim.x());
}

std::optional<double> safetyValue(const Trial& trial, const TableView& view) {
  if (!trial.judged || trial.loses || trial.dead_layout || !trial.verdict.legal()) {
    return std::nullopt;
  }
  if (trial.wins) return 1000.0;
  return 50.0 + 10.0 * (1.0 - shooterChances(trial.after, trial.verdict.next, view));
}

// Tries a declared safety along `yaw` at `speed` (the cue ball placed at `place` first, when in
// hand) and keeps it in `best` if it is legal and worth more. False once the budget is spent.
bool trySafety(PlanContext& context, double yaw, double speed, const std::optional<Vec2>& place,
               std::optional<PlannedShot>& best) {
  PlannedShot shot = context.blank(ShotKind::Safety);
  shot.cue = stroke(yaw, speed);
  shot.safety = true;
  shot.cue_ball_at = place;
  const auto trial = context.tryShot(shot);
  if (!trial) return false;
  if (const auto value = safetyValue(*trial, context.view)) {
    shot.value = *value;
    if (!best || shot.value > best->value) best = shot;
  }
  return true;
}

void trySafetiesFrom(PlanContext& context, const Vec2& from, const std::optional<Vec2>& place,
                     std::optional<PlannedShot>& best) {
  const double r = context.view.radius();
  for (int id : context.directBalls()) {
    const auto object = ballAt(context.balls, id);
    if (!object || !pathClear(from, *object - 2 * r * (*object - from).normalized(), context.balls,
                              r, physics::kCueBall, id)) {
      continue;
    }
    for (double offset : kContact) {
      for (double speed : kSafetySpeeds) {
        if (!trySafety(context, aimWithOffset(from, *object, offset, r), speed, place, best)) {
          return;
        }
      }
    }
  }
}

// Kicks: off one cushion onto a legal ball, aimed at the ball's mirror image in the line the
// cue ball's centre runs along that cushion (a ball radius off its nose): for when no direct hit
// makes a legal safety (from where the cue ball lies; not yet from hand). Each is verified in the
// physics like any safety.
void tryKicksFrom(PlanContext& context, const Vec2& from, const std::optional<Vec2>& place,
                  std::optional<PlannedShot>& best) {
  const double r = context.view.radius();
  const double x_rail = context.view.halfLength() - r, y_rail = context.view.halfWidth() - r;
  for (int id : context.legalBalls()) {
    const auto object = ballAt(context.balls, id);
    if (!object) continue;
    const std::array<Vec2, 4> images{
        Vec2(2 * x_rail - object->x(), object->y()), Vec2(-2 * x_rail - object->x(), object->y()),
        Vec2(object->x(), 2 * y_rail - object->y()), Vec2(object->x(), -2 * y_rail - object->y())};
    for (const Vec2& image : images) {
      for (double speed : kKickSpeeds) {
        const double yaw = std::atan2(image.y() - from.y(), image.x() - from.x());
        if (!trySafety(context, yaw, speed, place, best)) return;
      }
    }
  }
}

}  // namespace

std::optional<PlannedShot> searchSafety(PlanContext& context, const std::vector<Vec2>& spots) {
  std::optional<PlannedShot> best;
  if (spots.empty()) {
    const auto cue = ballAt(context.balls, physics::kCueBall);
    if (!cue) return best;
    trySafetiesFrom(context, *cue, std::nullopt, best);
    if (!best) tryKicksFrom(context, *cue, std::nullopt, best);
    return best;
  }
  for (const Vec2& spot : spots) trySafetiesFrom(context, spot, spot, best);
  return best;
}

PlannedShot fallbackShot(const PlanContext& context, const std::optional<Vec2>& spot) {
  PlannedShot shot = context.blank(ShotKind::Fallback);
  shot.safety = true;
  shot.cue_ball_at = spot;
  const Vec2 from = spot ? *spot : ballAt(context.balls, physics::kCueBall).value_or(Vec2::Zero());
  auto targets = context.directBalls();
  if (targets.empty()) {
    for (const auto& b : context.balls) {
      if (b.id != physics::kCueBall && physics::onTable(b.state)) targets.push_back(b.id);
    }
  }
  double nearest = std::numeric_limits<double>::infinity();
  double yaw = 0.0;
  for (int id : targets) {
    const auto object = ballAt(context.balls, id);
    if (!object || (*object - from).norm() >= nearest) continue;
    nearest = (*object - from).norm();
    yaw = std::atan2(object->y() - from.y(), object->x() - from.x());
  }
  shot.cue = stroke(yaw, kFallbackSpeed);
  return shot;
}

}  // namespace pool::bot
