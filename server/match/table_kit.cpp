// Loading a table for matches and laying out a fresh rack.
#include "server/match/table_kit.h"

#include <algorithm>

#include "table/rack.h"

namespace pool::server {

Result<std::shared_ptr<const TableKit>> loadTableKit(const std::string& name) {
  using Out = Result<std::shared_ptr<const TableKit>>;
  auto spec = table::loadTableSpec(name);
  if (!spec) return Out::fail("table " + name + ": " + spec.error());
  auto geometry = table::loadTableGeometry(*spec);
  if (!geometry) return Out::fail("table " + name + ": " + geometry.error());
  auto kit = std::make_shared<TableKit>();
  kit->spec = std::move(*spec);
  kit->geometry = std::move(*geometry);
  kit->context = rules::tableContext(kit->spec, kit->geometry);
  return Out::ok(std::move(kit));
}

std::vector<physics::Ball> rackLayout(const TableKit& kit, std::uint64_t seed, table::RackType type,
                                      table::RackGenerator generator) {
  const double r = kit.context.ball_radius;
  const Eigen::Vector2d cue_at = kit.context.spots.head_spot - Eigen::Vector2d(kBreakCueSetback, 0);
  std::vector<physics::Ball> balls{physics::restingBall(physics::kCueBall, cue_at, r)};
  for (const auto& p : table::rackFor(type, kit.spec, r, seed, generator)) {
    balls.push_back(physics::restingBall(p.id, p.pos, r));
  }
  std::sort(balls.begin(), balls.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return balls;
}

}  // namespace pool::server
