// Ghost-ball aim, cut angles, clear paths and the speed for a pot.
#include "client/bot/ai/ghost_ball.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "table/segment_distance.h"

namespace pool::bot {
namespace {

using table::segmentDistance;

// Widest angle between the object ball's path and the pocket's axis that still drops, rad.
constexpr double kCornerApproach = 1.15;
constexpr double kSideApproach = 0.95;
// Pace the object ball keeps at the pocket, m/s.
constexpr double kArrivalSpeed = 0.7;
constexpr double kMinSpeed = 0.6;
constexpr double kMaxSpeed = 6.5;

bool onSurface(const Vec2& p, const TableView& view) {
  const double r = view.radius();
  return std::abs(p.x()) <= view.halfLength() - r && std::abs(p.y()) <= view.halfWidth() - r;
}

bool enters(const PocketTarget& pocket, const Vec2& direction) {
  const double limit = pocket.corner ? kCornerApproach : kSideApproach;
  return std::acos(std::clamp(direction.dot(pocket.outward), -1.0, 1.0)) <= limit;
}

}  // namespace

std::optional<PotLine> potLine(const Vec2& cue, const Vec2& object, int id, int pocket,
                               const TableView& view) {
  const PocketTarget& target = view.pockets[static_cast<std::size_t>(pocket)];
  PotLine line;
  line.ball = id;
  line.pocket = pocket;
  line.cue = cue;
  line.object = object;
  line.target = target.mouth;
  const Vec2 to_pocket = target.mouth - object;
  line.object_distance = to_pocket.norm();
  if (line.object_distance < 1e-6) return std::nullopt;
  const Vec2 d = to_pocket / line.object_distance;
  if (!enters(target, d)) return std::nullopt;
  if (!aimLine(line, d, view)) return std::nullopt;
  return line;
}

bool aimLine(PotLine& line, const Vec2& direction, const TableView& view) {
  line.ghost = line.object - 2 * view.radius() * direction;
  const Vec2 to_ghost = line.ghost - line.cue;
  line.cue_distance = to_ghost.norm();
  if (line.cue_distance < 1e-6 || !onSurface(line.ghost, view)) return false;
  const Vec2 aim = to_ghost / line.cue_distance;
  line.cut = std::acos(std::clamp(aim.dot(direction), -1.0, 1.0));
  if (line.cut > kMaxCut) return false;
  line.yaw = std::atan2(aim.y(), aim.x());
  // Error in the object ball's direction grows with its distance and with the cut.
  const double cos_cut = std::max(std::cos(line.cut), 0.05);
  line.difficulty = (line.object_distance + 0.35 * line.cue_distance) / std::pow(cos_cut, 1.5);
  return true;
}

std::optional<Vec2> contactLine(const Vec2& cue, const Vec2& object, double yaw, double radius) {
  const Vec2 u(std::cos(yaw), std::sin(yaw));
  const Vec2 w = object - cue;
  const double along = w.dot(u);
  const double off_squared = w.squaredNorm() - along * along;
  const double reach = 4 * radius * radius;
  if (along <= 0.0 || off_squared >= reach) return std::nullopt;
  const Vec2 at_contact = cue + (along - std::sqrt(reach - off_squared)) * u;
  return (object - at_contact).normalized();
}

bool pathClear(const Vec2& from, const Vec2& to, const std::vector<physics::Ball>& balls,
               double radius, int ignore_a, int ignore_b) {
  // Slightly less than touching: balls frozen together still let a shot past.
  const double clearance = 2 * radius - 1e-4;
  for (const auto& b : balls) {
    if (!physics::onTable(b.state) || b.id == ignore_a || b.id == ignore_b) continue;
    if (segmentDistance(b.pos.head<2>(), from, to) < clearance) return false;
  }
  return true;
}

std::vector<PotLine> potLines(const Vec2& cue, const std::vector<physics::Ball>& balls,
                              const std::vector<int>& legal, const TableView& view) {
  std::vector<PotLine> lines;
  const double r = view.radius();
  for (int id : legal) {
    const auto object = ballAt(balls, id);
    if (!object) continue;
    for (int p = 0; p < static_cast<int>(view.pockets.size()); ++p) {
      auto line = potLine(cue, *object, id, p, view);
      if (!line) continue;
      if (!pathClear(*object, line->target, balls, r, id, physics::kCueBall)) continue;
      if (!pathClear(cue, line->ghost, balls, r, physics::kCueBall, id)) continue;
      lines.push_back(*line);
    }
  }
  std::sort(lines.begin(), lines.end(),
            [](const PotLine& a, const PotLine& b) { return a.difficulty < b.difficulty; });
  return lines;
}

double potSpeed(const PotLine& line, const table::PhysicsParams& params) {
  const double roll_decel = params.u_r * physics::kGravity;
  // A struck or hit ball slides first and keeps 5/7 of its speed once it rolls.
  constexpr double kSlideLoss = 7.0 / 5.0;
  const double object_roll =
      std::sqrt(kArrivalSpeed * kArrivalSpeed + 2 * roll_decel * line.object_distance);
  const double transfer = std::max(std::cos(line.cut), 0.2) * (1 + params.e_b) / 2;
  const double cue_at_contact = kSlideLoss * object_roll / transfer;
  const double cue_roll =
      std::sqrt(cue_at_contact * cue_at_contact + 2 * roll_decel * line.cue_distance);
  return std::clamp(kSlideLoss * cue_roll, kMinSpeed, kMaxSpeed);
}

double angleOf(const Vec2& v) {
  return std::atan2(v.y(), v.x());
}

double angleBetween(double a, double b) {
  return std::remainder(a - b, 2.0 * std::numbers::pi);
}

std::optional<Vec2> ballAt(const std::vector<physics::Ball>& balls, int id) {
  for (const auto& b : balls) {
    if (b.id == id && physics::onTable(b.state)) return Vec2(b.pos.head<2>());
  }
  return std::nullopt;
}

}  // namespace pool::bot
