// Grid search for a legal cue-ball placement.
#include "client/app/placement_search.h"

#include <cmath>
#include <limits>

#include "rules/placement.h"

namespace pool::app {

std::optional<Eigen::Vector2d> nearestLegalPlacement(rules::BallInHand in_hand,
                                                     const Eigen::Vector2d& wanted,
                                                     const std::vector<physics::Ball>& balls,
                                                     const rules::TableContext& table,
                                                     double max_distance) {
  auto legal = [&](const Eigen::Vector2d& at) {
    return rules::checkCueBallPlacement(in_hand, at, balls, table).ok();
  };
  if (legal(wanted)) return wanted;
  const double step = table.ball_radius / 2;
  const int reach = static_cast<int>(std::ceil(max_distance / step));
  std::optional<Eigen::Vector2d> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = -reach; i <= reach; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      const Eigen::Vector2d offset(i * step, j * step);
      const double distance = offset.norm();
      if (distance > max_distance || distance >= best_distance) continue;
      if (!legal(wanted + offset)) continue;
      best = wanted + offset;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace pool::app
