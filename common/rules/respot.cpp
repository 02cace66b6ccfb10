// Where re-spotted balls go.
#include "rules/respot.h"

#include <algorithm>

namespace pool::rules {

std::vector<Respot> respotBalls(const std::vector<int>& ids,
                                const std::vector<physics::Ball>& balls,
                                const TableContext& table) {
  std::vector<Eigen::Vector2d> occupied;
  for (const auto& b : balls) {
    bool moving_back = std::find(ids.begin(), ids.end(), b.id) != ids.end();
    if (physics::onTable(b.state) && !moving_back) occupied.push_back(b.pos.head<2>());
  }
  std::vector<Respot> respots;
  for (int id : ids) {
    Eigen::Vector2d pos = table::respotPosition(table.spec, table.ball_radius, occupied);
    respots.push_back({id, pos});
    occupied.push_back(pos);
  }
  return respots;
}

}  // namespace pool::rules
