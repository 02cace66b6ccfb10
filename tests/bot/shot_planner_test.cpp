// The bot's shot choice: straight pots found and verified, blocked balls avoided, the 8 only
// when it is on, safeties when nothing is, the break.
#include <gtest/gtest.h>

#include <cmath>

#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/shot_verifier.h"
#include "rules/eight_ball.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

TEST(ShotPlannerTest, StraightInShotIsFoundAndPotsInThePhysics) {
  const Vec2 object = onPocketLine("foot_left_corner", Vec2::Zero(), 0.6);
  const Vec2 cue = onPocketLine("foot_left_corner", Vec2::Zero(), 1.2);
  const auto balls = layout({resting(0, cue.x(), cue.y()), resting(3, object.x(), object.y()),
                             resting(8, -0.8, -0.4), resting(12, 0.9, -0.45)});
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, solidsToShoot());
  ASSERT_EQ(shot.kind, ShotKind::Pot) << describe(shot);
  EXPECT_EQ(shot.called_ball, 3);
  EXPECT_EQ(shot.called_pocket, "foot_left_corner");
  EXPECT_FALSE(shot.cue_ball_at);
  // The chosen stroke, replayed on its own, pockets the 3 legally and keeps the turn.
  ShotVerifier verifier(nineFoot());
  const Trial trial = verifier.run(balls, solidsToShoot(), shot);
  ASSERT_TRUE(trial.judged) << trial.error;
  EXPECT_TRUE(trial.potted_call);
  EXPECT_TRUE(trial.verdict.legal());
  EXPECT_TRUE(trial.verdict.turn_continues);
}

TEST(ShotPlannerTest, ABlockedBallIsNotCalled) {
  // The 3 sits straight in front of a pocket but a stripe stands between it and the cue ball;
  // the 5 has an open, longer shot.
  const Vec2 object = onPocketLine("foot_left_corner", Vec2::Zero(), 0.5);
  const Vec2 cue = onPocketLine("foot_left_corner", Vec2::Zero(), 1.3);
  const Vec2 blocker = onPocketLine("foot_left_corner", Vec2::Zero(), 0.9);
  const auto balls = layout({resting(0, cue.x(), cue.y()), resting(3, object.x(), object.y()),
                             resting(10, blocker.x(), blocker.y()), resting(5, -0.6, -0.4),
                             resting(8, 1.0, -0.1)});
  EXPECT_FALSE(pathClear(cue, object, balls, nineFoot().radius(), 0, 3));
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, solidsToShoot());
  EXPECT_NE(shot.called_ball, 3) << describe(shot);
  if (shot.kind == ShotKind::Pot) {
    EXPECT_EQ(shot.called_ball, 5);
  }
}

TEST(ShotPlannerTest, TheEightIsCalledOnlyWhenItIsTheLegalBall) {
  // An easy 8 and a harder solid: the solid is called while it is on the table.
  const Vec2 eight = onPocketLine("head_right_corner", Vec2::Zero(), 0.3);
  const auto with_solid = layout({resting(0, 0.0, 0.0), resting(8, eight.x(), eight.y()),
                                  resting(6, 0.8, 0.45), resting(14, -0.2, 0.5)});
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(with_solid, solidsToShoot());
  EXPECT_NE(shot.called_ball, 8) << describe(shot);
  // Once the solids are gone the 8 is the shot, and pocketing it wins.
  const auto on_eight =
      layout({resting(0, 0.0, 0.0), resting(8, eight.x(), eight.y()), resting(14, -0.2, 0.5)});
  ASSERT_TRUE(rules::onTheEight(solidsToShoot(), on_eight));
  const PlannedShot final_shot = planner.plan(on_eight, solidsToShoot());
  ASSERT_EQ(final_shot.kind, ShotKind::Pot) << describe(final_shot);
  EXPECT_EQ(final_shot.called_ball, 8);
  EXPECT_GE(final_shot.value, 1000.0);
}

TEST(ShotPlannerTest, NothingOnGivesADeclaredSafety) {
  // The only solid is walled off from every pocket by stripes.
  const Vec2 one(0.3, 0.0);
  std::vector<physics::Ball> balls = layout({resting(0, 0.9, 0.0), resting(1, one.x(), one.y())});
  int stripe = 9;
  for (const auto& pocket : nineFoot().pockets) {
    const Vec2 b = one + (pocket.mouth - one).normalized() * 4 * nineFoot().radius();
    balls[static_cast<std::size_t>(stripe)] = resting(stripe, b.x(), b.y());
    ++stripe;
  }
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, solidsToShoot());
  EXPECT_TRUE(shot.kind == ShotKind::Safety || shot.kind == ShotKind::Fallback) << describe(shot);
  EXPECT_TRUE(shot.safety);
  EXPECT_FALSE(shot.called_ball);
}

// No legal ball can be hit directly: the only solid sits behind a wall of stripes. The bot kicks
// off a cushion (aimed at the ball's mirror image in the cushion) instead of a blind hit at the
// nearest ball, which fouls (wrong ball first): the kick it plays is legal in the physics.
TEST(ShotPlannerTest, AHiddenBallIsKickedAtOffACushionLegally) {
  const auto& view = nineFoot();
  const double r = view.radius();
  // The one-cushion kick off either long rail meets it at x = -0.35, clear of the side pockets.
  std::vector<physics::Ball> balls = layout({resting(0, -0.9, 0.0), resting(1, 0.2, 0.0)});
  // Stripes 9-15 in a column across the table between them, 3.0 R apart (a gap too narrow for
  // the cue ball to pass): every direct path to the 1 is blocked.
  for (int k = 0; k < 7; ++k) {
    const int id = 9 + k;
    balls[static_cast<std::size_t>(id)] = resting(id, -0.5, (k - 3) * 3.0 * r);
  }
  ShotPlanner planner(view);
  const rules::GameState state = solidsToShoot();
  const PlannedShot shot = planner.plan(balls, state);
  ASSERT_EQ(shot.kind, ShotKind::Safety) << describe(shot);
  ShotVerifier verifier(view);
  const Trial trial = verifier.run(balls, state, shot);
  ASSERT_TRUE(trial.judged) << trial.error;
  EXPECT_TRUE(trial.verdict.legal()) << rules::describe(trial.verdict);
  // Not a direct line at the 1: the cue ball heads away from the straight line to it.
  EXPECT_GT(std::abs(std::sin(shot.cue.yaw)), 0.2) << describe(shot);
}

// Ball in hand behind the head string (after a scratch on the break): a ball that lies behind
// the head string too may not be played directly (rules: Foul::BehindHeadStringDirect). Three
// solids sit in the kitchen with easy lines; the only legal pot is the 5, beyond the head string.
TEST(ShotPlannerTest, FromTheKitchenTheOnlyLegalPotBeyondTheHeadStringIsPlayed) {
  const auto& view = nineFoot();
  const double hs = view.headStringX();
  const Vec2 five = onPocketLine("foot_left_corner", Vec2::Zero(), 0.35);
  ASSERT_GT(five.x(), hs);
  const auto balls =
      layout({resting(0, hs - 0.2, 0.0), resting(1, hs - 0.3, 0.35), resting(2, hs - 0.3, -0.35),
              resting(3, hs - 0.45, 0.1), resting(5, five.x(), five.y()), resting(8, 0.9, -0.45),
              resting(10, 0.2, -0.3), resting(12, -0.2, 0.45)});
  rules::GameState state = solidsToShoot();
  state.ball_in_hand = rules::BallInHand::BehindHeadString;
  ShotPlanner planner(view);
  const PlannedShot shot = planner.plan(balls, state);
  ASSERT_EQ(shot.kind, ShotKind::Pot) << describe(shot);
  EXPECT_EQ(shot.called_ball, 5);
  ASSERT_TRUE(shot.cue_ball_at);
  EXPECT_LT(shot.cue_ball_at->x(), hs);
  // Played on its own, it pockets the 5 legally.
  ShotVerifier verifier(view);
  auto placed = balls;
  placed[0] = resting(0, shot.cue_ball_at->x(), shot.cue_ball_at->y());
  const Trial trial = verifier.run(placed, state, shot);
  ASSERT_TRUE(trial.judged) << trial.error;
  EXPECT_TRUE(trial.verdict.legal());
  EXPECT_TRUE(trial.potted_call);
}

TEST(ShotPlannerTest, BreakIsFromBehindTheHeadStringAndHard) {
  std::vector<physics::Ball> balls{resting(0, 0.0, 0.0)};
  for (const auto& p :
       table::rackBalls(table::RackType::EightBall, nineFoot().spec, nineFoot().radius(), 7)) {
    balls.push_back(resting(p.id, p.pos.x(), p.pos.y()));
  }
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, rules::newRack(0));
  ASSERT_EQ(shot.kind, ShotKind::Break);
  ASSERT_TRUE(shot.cue_ball_at);
  EXPECT_LT(shot.cue_ball_at->x(), nineFoot().headStringX());
  EXPECT_GE(shot.cue.speed, 8.0);
  EXPECT_GT(shot.value, 0.0) << "no break tried was legal";
}

}  // namespace
}  // namespace pool::bot::test
