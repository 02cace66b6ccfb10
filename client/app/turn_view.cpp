// The heading a turn starts with.
#include "client/app/turn_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rules/ball_groups.h"
#include "rules/game_rules.h"

namespace pool::app {
namespace {

std::optional<double> nearest(const Eigen::Vector2d& cue, const std::vector<physics::Ball>& balls,
                              const std::vector<int>& allowed) {
  double best = std::numeric_limits<double>::infinity();
  std::optional<double> yaw;
  for (const auto& b : balls) {
    if (!physics::onTable(b.state) || !rules::isObjectBall(b.id)) continue;
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), b.id) == allowed.end()) {
      continue;
    }
    const Eigen::Vector2d to = b.pos.head<2>() - cue;
    const double d = to.norm();
    if (d < 1e-9 || d >= best) continue;
    best = d;
    yaw = std::atan2(to.y(), to.x());
  }
  return yaw;
}

}  // namespace

std::optional<double> turnStartYaw(const Eigen::Vector2d& cue,
                                   const std::vector<physics::Ball>& balls,
                                   const rules::GameState& state, rules::Game game) {
  const auto legal = rules::firstBallsFor(rules::GameRules{game, {}, {}}, state, balls);
  if (!legal.empty()) {
    if (auto yaw = nearest(cue, balls, legal)) return yaw;
  }
  return nearest(cue, balls, {});
}

}  // namespace pool::app
