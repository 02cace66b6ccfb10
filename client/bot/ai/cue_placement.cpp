// Candidate spots for the cue ball in hand.
#include "client/bot/ai/cue_placement.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "rules/placement.h"

namespace pool::bot {
namespace {

constexpr std::array<double, 3> kBackOff{0.18, 0.32, 0.5};           // m behind the ghost point
constexpr std::array<double, 5> kAngles{0.0, 0.3, -0.3, 0.6, -0.6};  // rad off the pot line
// Kitchen grid: distances behind the head string (m) and lateral steps.
constexpr std::array<double, 3> kKitchenDepth{0.02, 0.2, 0.4};
constexpr int kKitchenColumns = 9;

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

void addLinesFrom(const PlanContext& context, const Vec2& at, const std::vector<int>& legal,
                  const std::vector<physics::Ball>& table, std::vector<PotCandidate>& out) {
  for (const auto& line : potLines(at, table, legal, context.view)) {
    out.push_back(PotCandidate{line, at});
  }
}

// Spots behind the ghost point of every open line of every legal ball.
void addSpotsBehindGhosts(const PlanContext& context, const std::vector<int>& legal,
                          const std::vector<physics::Ball>& table, std::vector<PotCandidate>& out) {
  const double r = context.view.radius();
  for (int id : legal) {
    const auto object = ballAt(table, id);
    if (!object) continue;
    for (int p = 0; p < static_cast<int>(context.view.pockets.size()); ++p) {
      const Vec2 mouth = context.view.pockets[static_cast<std::size_t>(p)].mouth;
      const Vec2 d = (mouth - *object).normalized();
      const Vec2 ghost = *object - 2 * r * d;
      for (double back : kBackOff) {
        for (double angle : kAngles) {
          const Vec2 at = ghost - back * rotate(d, angle);
          if (!placementLegal(context, at)) continue;
          auto line = potLine(at, *object, id, p, context.view);
          if (!line || !pathClear(*object, line->target, table, r, id, physics::kCueBall) ||
              !pathClear(at, line->ghost, table, r, physics::kCueBall, id)) {
            continue;
          }
          out.push_back(PotCandidate{*line, at});
        }
      }
    }
  }
}

std::vector<Vec2> kitchenGrid(const PlanContext& context) {
  std::vector<Vec2> spots;
  const double hs = context.view.headStringX();
  const double half_w = context.view.halfWidth() - 2 * context.view.radius();
  for (double depth : kKitchenDepth) {
    for (int j = 0; j < kKitchenColumns; ++j) {
      const double y = -half_w + 2 * half_w * j / (kKitchenColumns - 1);
      const Vec2 at(hs - depth, y);
      if (placementLegal(context, at)) spots.push_back(at);
    }
  }
  return spots;
}

// Snooker: spots in the D, on rings about the brown spot across its baulk half.
std::vector<Vec2> dGrid(const PlanContext& context) {
  std::vector<Vec2> spots;
  const auto& d = context.view.context.snooker;
  if (!d) return spots;
  constexpr std::array<double, 4> kRings{0.0, 0.35, 0.7, 0.97};  // of the D's radius
  constexpr int kSteps = 7;                                      // across the half circle
  constexpr double kPi = 3.141592653589793;
  for (double ring : kRings) {
    for (int k = 0; k < (ring == 0.0 ? 1 : kSteps); ++k) {
      const double a = kPi / 2.0 + kPi * k / (kSteps - 1);  // +y round through baulk to −y
      const Vec2 at = d->brown + ring * d->d_radius * Vec2(std::cos(a), std::sin(a));
      if (placementLegal(context, at)) spots.push_back(at);
    }
  }
  return spots;
}

}  // namespace

std::vector<physics::Ball> withoutCueBall(const std::vector<physics::Ball>& balls) {
  std::vector<physics::Ball> out;
  for (const auto& b : balls) {
    if (b.id != physics::kCueBall) out.push_back(b);
  }
  return out;
}

bool placementLegal(const PlanContext& context, const Vec2& at) {
  return rules::checkCueBallPlacement(context.play_state.ball_in_hand, at,
                                      withoutCueBall(context.balls), context.view.context)
      .ok();
}

std::vector<PotCandidate> potsFromHand(const PlanContext& context) {
  const auto table = withoutCueBall(context.balls);
  const auto legal = context.directBalls();
  std::vector<PotCandidate> out;
  addSpotsBehindGhosts(context, legal, table, out);
  if (context.play_state.ball_in_hand == rules::BallInHand::BehindHeadString) {
    for (const Vec2& at : kitchenGrid(context)) addLinesFrom(context, at, legal, table, out);
  }
  if (context.play_state.ball_in_hand == rules::BallInHand::InTheD) {
    for (const Vec2& at : dGrid(context)) addLinesFrom(context, at, legal, table, out);
  }
  std::stable_sort(out.begin(), out.end(), [](const PotCandidate& a, const PotCandidate& b) {
    return a.line.difficulty < b.line.difficulty;
  });
  return out;
}

std::vector<Vec2> restingSpots(const PlanContext& context) {
  if (context.play_state.ball_in_hand == rules::BallInHand::InTheD) return dGrid(context);
  std::vector<Vec2> spots;
  const Vec2 head = context.view.context.spots.head_spot;
  const double hs = context.view.headStringX();
  const std::array<Vec2, 5> tries{Vec2(hs - 0.1, 0.0), Vec2(hs - 0.1, 0.25), Vec2(hs - 0.1, -0.25),
                                  Vec2(head.x() - 0.3, 0.0), Vec2(0.0, 0.0)};
  for (const Vec2& at : tries) {
    if (placementLegal(context, at)) spots.push_back(at);
  }
  if (spots.empty()) {
    for (const Vec2& at : kitchenGrid(context)) spots.push_back(at);
  }
  return spots;
}

}  // namespace pool::bot
