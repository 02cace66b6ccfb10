// Grading a leave: the next pot's chances, and the position each next pot offers on the one after.
#include "client/bot/ai/leave_value.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "rules/ball_groups.h"
#include "rules/game_rules.h"
#include "rules/rotation.h"

namespace pool::bot {
namespace {

// How far off its line (m, at the pocket) a ball sent straight at a pocket still drops.
constexpr double kPocketTolerance = 0.03;
// How many of a leave's balls are counted, and of a fan's spots.
constexpr std::size_t kBallsCounted = 3;
constexpr std::size_t kSpotsCounted = 3;
// What a next pot is worth with no position after it, as a share of one with position.
constexpr double kNoPositionShare = 0.25;
// Lengths (m) the cue ball is sent along each path of the fan after a pot; paths at each of
// kFanAngles angles from full follow to the most draw the cut allows.
constexpr std::array<double, 4> kFanLengths{0.15, 0.4, 0.75, 1.2};
constexpr int kFanAngles = 5;

// The ball whose legal pot ends the game, if the game has one.
int gameBall(const rules::GameRules& rules) {
  switch (rules.game) {
    case rules::Game::EightBall:
      return rules::kEightBall;
    case rules::Game::NineBall:
    case rules::Game::TenBall:
      return rules::rackBall(rules.rotation().game);
    default:
      return -1;
  }
}

// `p` folded back onto the cue ball's area of the bed (cushions reflect it).
Vec2 reflected(Vec2 p, const TableView& view) {
  const std::array<double, 2> half{view.halfLength() - view.radius(),
                                   view.halfWidth() - view.radius()};
  for (int axis = 0; axis < 2; ++axis) {
    const double h = half[static_cast<std::size_t>(axis)];
    double& v = p[axis];
    for (int k = 0; k < 4 && std::abs(v) > h; ++k) v = std::copysign(2 * h, v) - v;
    v = std::clamp(v, -h, h);
  }
  return p;
}

Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// The spots the cue ball can be sent to after potting `line`: deflected from its aim line by
// angles from a rolling ball's (tan θ = sin c cos c / (sin² c + 2/5): the "30° rule", Alciatore,
// "The Illustrated Principles of Pool and Billiards", TP A.4) to the most draw brings it round
// (90° - c for a stunned ball, up to 90° more for a full draw, less the thinner the cut), on the
// side away from the object ball.
std::vector<Vec2> reachSpots(const PotLine& line, const TableView& view) {
  const Vec2 aim = (line.ghost - line.cue).normalized();
  const Vec2 d = (line.target - line.object).normalized();
  const double c = line.cut;
  const double sin_c = std::sin(c), cos_c = std::cos(c);
  const double follow = std::atan2(sin_c * cos_c, sin_c * sin_c + 0.4);
  const double draw =
      std::min(std::numbers::pi, std::numbers::pi / 2 - c + std::numbers::pi / 2 * cos_c);
  // The object ball leaves on one side of the aim line; the cue ball goes to the other.
  const double cross = aim.x() * d.y() - aim.y() * d.x();
  const double side = cross > 0 ? -1.0 : 1.0;
  std::vector<Vec2> spots;
  spots.reserve(kFanAngles * kFanLengths.size());
  for (int k = 0; k < kFanAngles; ++k) {
    const double angle = follow + (draw - follow) * k / (kFanAngles - 1);
    const Vec2 dir = rotated(aim, side * angle);
    for (double length : kFanLengths) spots.push_back(reflected(line.ghost + length * dir, view));
  }
  return spots;
}

// The best chance of a clear pot on `legal` from a cue ball at `cue` (0 when there is none).
double bestChance(const Vec2& cue, const std::vector<physics::Ball>& balls,
                  const std::vector<int>& legal, const TableView& view, double yaw_sigma) {
  const double r = view.radius();
  double best = 0.0;
  for (int id : legal) {
    const auto object = ballAt(balls, id);
    if (!object) continue;
    for (int p = 0; p < static_cast<int>(view.pockets.size()); ++p) {
      const auto line = potLine(cue, *object, id, p, view);
      if (!line) continue;
      const double chance = makeChance(*line, yaw_sigma, view);
      if (chance <= best) continue;
      if (!pathClear(*object, line->target, balls, r, id, physics::kCueBall)) continue;
      if (!pathClear(cue, line->ghost, balls, r, physics::kCueBall, id)) continue;
      best = chance;
    }
  }
  return best;
}

// How well the cue ball can be placed for the ball after `line`'s: the mean of the best
// kSpotsCounted chances over the spots it can be sent to (a zone, not a point: speed is not exact).
double followChance(const PotLine& line, const std::vector<physics::Ball>& balls,
                    const rules::GameState& state, const TableView& view, double yaw_sigma) {
  std::vector<physics::Ball> after = balls;
  for (auto& b : after) {
    if (b.id == line.ball) b.state = physics::MotionState::Pocketed;
  }
  const auto legal = rules::firstBallsFor(view.rules, state, after);
  if (legal.empty()) return 1.0;
  std::vector<double> chances;
  const double clearance = 2 * view.radius();
  for (const Vec2& spot : reachSpots(line, view)) {
    const bool on_a_ball = std::any_of(after.begin(), after.end(), [&](const physics::Ball& b) {
      return physics::onTable(b.state) && b.id != physics::kCueBall &&
             (Vec2(b.pos.head<2>()) - spot).norm() < clearance;
    });
    if (!on_a_ball) chances.push_back(bestChance(spot, after, legal, view, yaw_sigma));
  }
  const std::size_t n = std::min(chances.size(), kSpotsCounted);
  if (n == 0) return 0.0;
  std::partial_sort(chances.begin(), chances.begin() + static_cast<std::ptrdiff_t>(n),
                    chances.end(), std::greater<>());
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += chances[i];
  return sum / static_cast<double>(n);
}

}  // namespace

double makeChance(const PotLine& line, double yaw_sigma, const TableView& view) {
  if (yaw_sigma <= 0.0) return 1.0;
  const auto& pocket = view.pockets[static_cast<std::size_t>(line.pocket)];
  const Vec2 along = (line.target - line.object).normalized();
  const double facing = std::max(0.3, along.dot(pocket.outward));
  const double tolerance = kPocketTolerance * facing / std::max(line.object_distance, 0.05);
  const double turn =
      line.cue_distance * yaw_sigma / (2.0 * view.radius() * std::max(std::cos(line.cut), 0.15));
  return std::erf(tolerance / (std::sqrt(2.0) * std::max(turn, 1e-9)));
}

double leaveValue(const std::vector<physics::Ball>& balls, const rules::GameState& state,
                  const TableView& view, double yaw_sigma, LookAhead look) {
  if (state.phase == rules::Phase::Over) return 0.0;
  if (state.ball_in_hand != rules::BallInHand::None) return 1.0;
  const auto cue = ballAt(balls, physics::kCueBall);
  if (!cue) return 1.0;
  // Each ball's most makeable clear line.
  std::vector<std::pair<PotLine, double>> best;
  for (const auto& line :
       potLines(*cue, balls, rules::firstBallsFor(view.rules, state, balls), view)) {
    const double chance = makeChance(line, yaw_sigma, view);
    auto it = std::find_if(best.begin(), best.end(),
                           [&](const auto& b) { return b.first.ball == line.ball; });
    if (it == best.end()) {
      best.emplace_back(line, chance);
    } else if (chance > it->second) {
      *it = {line, chance};
    }
  }
  std::sort(best.begin(), best.end(),
            [](const auto& a, const auto& b) { return a.second > b.second; });
  if (best.size() > kBallsCounted) best.resize(kBallsCounted);
  const bool two_shots = look == LookAhead::TwoShots && rules::isPool(view.rules.game);
  double miss_all = 1.0;
  for (const auto& [line, chance] : best) {
    double worth = chance;
    if (two_shots && line.ball != gameBall(view.rules)) {
      const double follow = followChance(line, balls, state, view, yaw_sigma);
      worth *= kNoPositionShare + (1.0 - kNoPositionShare) * follow;
    }
    miss_all *= 1.0 - worth;
  }
  return 1.0 - miss_all;
}

}  // namespace pool::bot
