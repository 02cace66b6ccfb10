// The layout a practice table's drag sends, with a lost cue ball put back, and its re-racks.
#include "client/app/practice_layout.h"

#include "client/app/placement_search.h"

namespace pool::app {

std::vector<protocol::BallSpot> layoutWithMove(const std::vector<physics::Ball>& balls, int id,
                                               const Eigen::Vector2d& at,
                                               const rules::TableContext& table) {
  std::vector<protocol::BallSpot> out;
  std::vector<physics::Ball> on_table;  // as they will lie, for finding the cue ball a place
  bool has_cue = id == physics::kCueBall;
  for (const auto& b : balls) {
    if (b.id == id) {
      out.push_back({id, at.x(), at.y()});
      on_table.push_back(physics::restingBall(id, at, table.ball_radius));
    } else if (physics::onTable(b.state)) {
      out.push_back({b.id, b.pos.x(), b.pos.y()});
      on_table.push_back(b);
      has_cue = has_cue || b.id == physics::kCueBall;
    }
  }
  if (!has_cue) {
    if (const auto spot = nearestLegalPlacement(rules::BallInHand::Anywhere, table.spots.head_spot,
                                                on_table, table)) {
      out.insert(out.begin(), {physics::kCueBall, spot->x(), spot->y()});
    }
  }
  return out;
}

int practiceRack(rules::Game table_game, int asked) {
  return rules::isPool(table_game) ? asked : rules::gameNumber(table_game);
}

}  // namespace pool::app
