// Pocket targets from the collision geometry: the jaw points are the rail noses' nearest ends.
#include "game/pocket_target.h"

#include <algorithm>
#include <utility>

namespace pool::game {
namespace {

using Vec2 = Eigen::Vector2d;

bool isJaw(const table::NoseSegment& nose) {
  return nose.name.rfind("jaw_", 0) == 0;
}

// The two rail-nose end points nearest a hole: the jaw points of its pocket.
std::pair<Vec2, Vec2> jawPoints(const table::TableGeometry& geometry, const Vec2& hole) {
  std::vector<Vec2> ends;
  for (const auto& nose : geometry.noses) {
    if (isJaw(nose)) continue;
    ends.push_back(nose.a);
    ends.push_back(nose.b);
  }
  std::sort(ends.begin(), ends.end(), [&](const Vec2& p, const Vec2& q) {
    return (p - hole).squaredNorm() < (q - hole).squaredNorm();
  });
  if (ends.size() < 2) return {hole, hole};
  return {ends[0], ends[1]};
}

PocketTarget targetFor(const table::TableGeometry& geometry, const table::PocketHole& hole) {
  PocketTarget target;
  target.name = hole.name;
  target.hole = hole.centre;
  const auto [a, b] = jawPoints(geometry, hole.centre);
  target.mouth = (a + b) / 2;
  const Vec2 out = hole.centre - target.mouth;
  target.outward = out.norm() > 1e-9 ? Vec2(out.normalized()) : Vec2(hole.centre.normalized());
  target.corner = hole.name.find("corner") != std::string::npos;
  return target;
}

}  // namespace

std::vector<PocketTarget> pocketTargets(const table::TableGeometry& geometry) {
  std::vector<PocketTarget> targets;
  for (const auto& hole : geometry.holes) targets.push_back(targetFor(geometry, hole));
  return targets;
}

}  // namespace pool::game
