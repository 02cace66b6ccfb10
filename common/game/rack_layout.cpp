// Laying out a fresh rack on a loaded table.
#include "game/rack_layout.h"

#include <algorithm>

namespace pool::game {

std::vector<physics::Ball> rackLayout(const LoadedTable& table, std::uint64_t seed,
                                      table::RackType type, table::RackGenerator generator) {
  const double r = table.context.ball_radius;
  const Eigen::Vector2d cue_at =
      table.context.spots.head_spot - Eigen::Vector2d(kBreakCueSetback, 0);
  std::vector<physics::Ball> balls;
  for (const auto& p : table::rackFor(type, table.spec, r, seed, generator)) {
    balls.push_back(physics::restingBall(p.id, p.pos, r));
  }
  // A pool rack is its object balls; the cue ball waits behind the head spot for the break. (A
  // carom opening places its cue balls itself.)
  const bool has_cue = std::any_of(balls.begin(), balls.end(),
                                   [](const auto& b) { return b.id == physics::kCueBall; });
  if (!has_cue) balls.push_back(physics::restingBall(physics::kCueBall, cue_at, r));
  std::sort(balls.begin(), balls.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return balls;
}

}  // namespace pool::game
