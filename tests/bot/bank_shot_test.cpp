// Bank pots: the mirror lines obey the law of reflection at the cushion, and a bot that banks
// pots the only legal ball when every direct line to a pocket is blocked.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "client/bot/ai/bank_shot.h"
#include "client/bot/ai/bot_level.h"
#include "client/bot/ai/shot_verifier.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

// Ball 1 on the long string in the foot half, a stripe 25 cm from it on its way to each of the
// six pockets, the cue ball at `cue`, the 8 far away: no direct pot, banks off the cushions.
std::vector<physics::Ball> directLinesBlocked(const Vec2& cue) {
  const auto& view = nineFoot();
  const Vec2 one(0.9, 0.0);
  std::vector<physics::Ball> on{resting(0, cue.x(), cue.y()), resting(1, one.x(), one.y()),
                                resting(8, -1.0, -0.5)};
  int id = 9;
  for (const auto& pocket : view.pockets) {
    const Vec2 at = one + 0.25 * (pocket.mouth - one).normalized();
    on.push_back(resting(id++, at.x(), at.y()));
  }
  auto balls = layout({});
  for (const auto& b : on) balls[static_cast<std::size_t>(b.id)] = b;
  return balls;
}

const Vec2 kCue(0.8, -0.35);

TEST(BankShot, EachBankLeavesTheCushionAtTheAngleItMeetsIt) {
  const auto& view = nineFoot();
  const double r = view.radius();
  const double hx = view.halfLength() - r, hy = view.halfWidth() - r;
  const auto balls = directLinesBlocked(kCue);
  // The mirror's own lines (no shift along the cushion).
  constexpr std::array<double, 1> kMirror{0.0};
  const auto banks = bankLines(kCue, balls, {1}, view, kMirror);
  ASSERT_FALSE(banks.empty());
  for (const auto& line : banks) {
    // The cushion crossed: the one the mirror image lies beyond.
    const int axis = std::abs(line.target.x()) > hx ? 0 : 1;
    ASSERT_TRUE(std::abs(line.target[axis]) > (axis == 0 ? hx : hy));
    const double at = std::copysign(axis == 0 ? hx : hy, line.target[axis]);
    const Vec2 way = line.target - line.object;
    const Vec2 bounce = line.object + (at - line.object[axis]) / way[axis] * way;
    const Vec2 mouth = view.pockets[static_cast<std::size_t>(line.pocket)].mouth;
    const Vec2 in = (bounce - line.object).normalized(), out = (mouth - bounce).normalized();
    // The law of reflection (a mirror cushion): the component along the cushion is kept, the one
    // across it reversed. Tolerance: rounding only.
    EXPECT_NEAR(out[1 - axis], in[1 - axis], 1e-9);
    EXPECT_NEAR(out[axis], -in[axis], 1e-9);
    EXPECT_LE(std::abs(bounce[1 - axis]), (axis == 0 ? hy : hx));
  }
}

TEST(BankShot, WithEveryDirectLineBlockedTheProBanksTheBallIn) {
  const auto& view = nineFoot();
  const auto balls = directLinesBlocked(kCue);
  const auto state = solidsToShoot();
  ASSERT_TRUE(potLines(kCue, balls, {1}, view).empty());
  ShotPlanner planner(view, plannerOptionsFor(Level::Pro, view.radius()));
  const PlannedShot shot = planner.plan(balls, state);
  ASSERT_EQ(shot.kind, ShotKind::Pot) << describe(shot);
  EXPECT_EQ(shot.called_ball, 1);
  // Played as planned (no stroke error), the physics sinks it in the called pocket.
  ShotVerifier verifier(view);
  const Trial trial = verifier.run(balls, state, shot);
  ASSERT_TRUE(trial.judged) << trial.error;
  EXPECT_TRUE(trial.potted_call) << describe(shot);
  EXPECT_TRUE(trial.verdict.legal());
}

}  // namespace
}  // namespace pool::bot::test
