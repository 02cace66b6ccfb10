// First-contact prediction along the cue line, the call it suggests and what a click may call.
#include "client/app/aim_line.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rules/game_rules.h"

namespace pool::app {
namespace {

// Distance along unit `dir` to the box |x| <= hx, |y| <= hy from inside it.
double toCushion(const Eigen::Vector2d& from, const Eigen::Vector2d& dir, double hx, double hy) {
  double t = std::numeric_limits<double>::infinity();
  if (dir.x() > 0) t = std::min(t, (hx - from.x()) / dir.x());
  if (dir.x() < 0) t = std::min(t, (-hx - from.x()) / dir.x());
  if (dir.y() > 0) t = std::min(t, (hy - from.y()) / dir.y());
  if (dir.y() < 0) t = std::min(t, (-hy - from.y()) / dir.y());
  return std::max(t, 0.0);
}

int closestPocket(const Eigen::Vector2d& at, const Eigen::Vector2d& heading,
                  const game::LoadedTable& view) {
  int best = -1;
  double best_cos = -2.0;
  for (std::size_t i = 0; i < view.pockets.size(); ++i) {
    const Eigen::Vector2d to = view.pockets[i].mouth - at;
    if (to.norm() < 1e-9) return static_cast<int>(i);
    const double c = heading.dot(to.normalized());
    if (c > best_cos) {
      best_cos = c;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace

double sweep(const Eigen::Vector2d& from, const Eigen::Vector2d& dir, const Eigen::Vector2d& centre,
             double reach) {
  const Eigen::Vector2d rel = centre - from;
  const double along = rel.dot(dir);
  const double miss2 = rel.squaredNorm() - along * along;
  if (along <= 0 || miss2 >= reach * reach) return std::numeric_limits<double>::infinity();
  return along - std::sqrt(reach * reach - miss2);
}

AimPrediction predictAim(const Eigen::Vector2d& cue, double yaw,
                         const std::vector<physics::Ball>& balls, const game::LoadedTable& view,
                         int struck) {
  const double r = view.radius();
  const Eigen::Vector2d dir(std::cos(yaw), std::sin(yaw));
  AimPrediction out;
  out.from = cue;
  double best = toCushion(cue, dir, view.halfLength() - r, view.halfWidth() - r);
  for (const auto& b : balls) {
    if (b.id == struck || !physics::onTable(b.state)) continue;
    const double t = sweep(cue, dir, b.pos.head<2>(), 2 * r);
    if (t < best) {
      best = t;
      out.ball = b.id;
    }
  }
  out.contact = cue + best * dir;
  if (out.ball) {
    const auto it = std::find_if(balls.begin(), balls.end(),
                                 [&](const physics::Ball& b) { return b.id == *out.ball; });
    const Eigen::Vector2d centre = it->pos.head<2>();
    out.object_dir = (centre - out.contact).normalized();
    out.pocket = closestPocket(centre, out.object_dir, view);
  }
  return out;
}

ShotCall autoCall(const AimPrediction& aim, const rules::GameState& state,
                  const std::vector<physics::Ball>& balls, const game::LoadedTable& view,
                  rules::Game game) {
  ShotCall call;
  if (state.phase == rules::Phase::Break || state.phase == rules::Phase::Over) return call;
  // 9-ball needs no call; three-cushion has nothing to call and no safety to declare; snooker
  // calls no pocket, and the colour (or free ball) the cue ball hits first is the one nominated.
  if (game == rules::Game::NineBall || game == rules::Game::ThreeCushion ||
      game == rules::Game::Snooker) {
    return call;
  }
  const auto legal = rules::firstBallsFor(rules::GameRules{game, {}, {}}, state, balls);
  const bool callable = aim.ball && aim.pocket >= 0 &&
                        std::find(legal.begin(), legal.end(), *aim.ball) != legal.end();
  if (!callable) {
    call.safety = true;
    return call;
  }
  call.ball = aim.ball;
  call.pocket = view.pockets[static_cast<std::size_t>(aim.pocket)].name;
  return call;
}

ClickTargets clickTargetsFor(rules::Game game, const std::vector<physics::Ball>& balls, int struck,
                             const game::LoadedTable& view) {
  ClickTargets targets;
  for (const auto& b : balls) {
    if (b.id != struck && physics::onTable(b.state))
      targets.balls.emplace_back(b.id, b.pos.head<2>());
  }
  if (game != rules::Game::Snooker) {
    for (const auto& p : view.pockets) targets.pockets.emplace_back(p.name, p.mouth);
  }
  return targets;
}

std::optional<std::vector<int>> nominableFor(rules::Game game, const rules::GameState& state,
                                             const std::vector<physics::Ball>& balls) {
  if (game != rules::Game::Snooker) return std::nullopt;
  const rules::GameRules played{game, {}, {}};
  std::vector<int> out;
  for (const auto& b : balls) {
    if (b.id == physics::kCueBall || !physics::onTable(b.state)) continue;
    rules::Intent nominated;
    nominated.ball = b.id;
    if (rules::checkIntentFor(played, state, nominated, balls).ok()) out.push_back(b.id);
  }
  return out;
}

}  // namespace pool::app
