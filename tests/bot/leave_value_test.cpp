// Grading a leave two shots ahead: a next pot after which the cue ball can see no other ball
// keeps a quarter of its worth, one that leaves position nearly all; the game ball needs none.
#include <gtest/gtest.h>

#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/leave_value.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

// The olympiad aim error (the pro's): the chances are those a strong player would have.
double proYaw() {
  return olympiadNoise(nineFoot().radius()).yaw;
}

// Solids to shoot: ball 1 straight in line with the foot left corner, 0.6 m from its mouth,
// the cue ball 0.3 m behind it; the 8 on the table; and ball 2 at `two` with stripes at `guards`.
std::vector<physics::Ball> oneThenTwo(const Vec2& two, std::initializer_list<Vec2> guards) {
  const Vec2 toward(-0.2, 0.1);
  const Vec2 one = onPocketLine("foot_left_corner", toward, 0.6);
  const Vec2 cue = onPocketLine("foot_left_corner", toward, 0.9);
  auto balls = layout({resting(0, cue.x(), cue.y()), resting(1, one.x(), one.y()),
                       resting(2, two.x(), two.y()), resting(8, -0.9, -0.45)});
  int id = 9;
  for (const Vec2& g : guards) {
    balls[static_cast<std::size_t>(id)] = resting(id, g.x(), g.y());
    ++id;
  }
  return balls;
}

// Ball 2 frozen to the middle of the foot cushion, a stripe frozen to it on each side along the
// cushion and one in front: every path from it to a pocket runs into a stripe, from wherever the
// cue ball might stand.
std::vector<physics::Ball> twoTrapped() {
  const auto& view = nineFoot();
  const double r = view.radius();
  const double x = view.halfLength() - r;
  return oneThenTwo(Vec2(x, 0.0), {Vec2(x, 2 * r), Vec2(x, -2 * r), Vec2(x - 2 * r, 0.0)});
}

TEST(LeaveValue, APotThatLeavesNoPositionOnTheBallAfterItCountsAQuarter) {
  const auto& view = nineFoot();
  const auto balls = twoTrapped();
  const double next = leaveValue(balls, solidsToShoot(), view, proYaw(), LookAhead::NextShot);
  const double two = leaveValue(balls, solidsToShoot(), view, proYaw(), LookAhead::TwoShots);
  // Ball 2 has no clear line, so the next shot's chances are ball 1's alone: a straight pot of
  // 0.6 m from 0.3 m, nearly sure under the olympiad aim error (0.125 deg: the object ball about
  // 1 mm off at the pocket, which takes 3 cm).
  EXPECT_GT(next, 0.99);
  // Two shots ahead: after ball 1 only ball 2 is on, and no spot offers a line on it, so ball 1
  // counts at the share a pot without position keeps (0.25 of its chance), exactly.
  EXPECT_NEAR(two, 0.25 * next, 1e-12);
}

TEST(LeaveValue, APotThatLeavesPositionKeepsNearlyAllItsWorth) {
  const auto& view = nineFoot();
  const double r = view.radius();
  const double x = view.halfLength() - r;
  // The same stripes on the foot cushion, ball 2 out in the open in the other half of the table:
  // the cue ball sent off ball 1 (follow, stun or draw) finds it with a straight or gentle pot.
  const auto balls =
      oneThenTwo(Vec2(-0.3, -0.25), {Vec2(x, 2 * r), Vec2(x, -2 * r), Vec2(x - 2 * r, 0.0)});
  const double next = leaveValue(balls, solidsToShoot(), view, proYaw(), LookAhead::NextShot);
  const double two = leaveValue(balls, solidsToShoot(), view, proYaw(), LookAhead::TwoShots);
  EXPECT_GT(next, 0.99);
  EXPECT_LE(two, next);
  // Its worth is 0.25 + 0.75 x follow, follow the mean chance of the three best spots' next pots:
  // above 0.75 when those pots go in more than two times in three (the trapped layout: 0.25).
  EXPECT_GT(two, 0.75 * next);
}

TEST(LeaveValue, TheGameBallNeedsNoPositionAfterIt) {
  const auto& view = nineFoot();
  // Only the 8 left for solids, straight in line with the foot left corner.
  const Vec2 toward(-0.2, 0.1);
  const Vec2 eight = onPocketLine("foot_left_corner", toward, 0.6);
  const Vec2 cue = onPocketLine("foot_left_corner", toward, 0.9);
  const auto balls = layout(
      {resting(0, cue.x(), cue.y()), resting(8, eight.x(), eight.y()), resting(12, -0.5, 0.3)});
  const double next = leaveValue(balls, solidsToShoot(), view, proYaw(), LookAhead::NextShot);
  const double two = leaveValue(balls, solidsToShoot(), view, proYaw(), LookAhead::TwoShots);
  EXPECT_GT(next, 0.99);
  EXPECT_DOUBLE_EQ(two, next);
}

TEST(LeaveValue, NoPotNextIsWorthNothingAndBallInHandEverything) {
  const auto& view = nineFoot();
  auto state = solidsToShoot();
  // Ball 2 trapped and ball 1 gone: nothing to shoot at.
  auto balls = twoTrapped();
  balls[1] = pocketed(1);
  EXPECT_EQ(leaveValue(balls, state, view, proYaw(), LookAhead::TwoShots), 0.0);
  state.ball_in_hand = rules::BallInHand::Anywhere;
  EXPECT_EQ(leaveValue(balls, state, view, proYaw(), LookAhead::TwoShots), 1.0);
}

}  // namespace
}  // namespace pool::bot::test
