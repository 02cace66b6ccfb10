// Ball in hand: every spot the bot picks passes the rules' placement check, and behind the head
// string stays strictly behind it.
#include <gtest/gtest.h>

#include "client/bot/ai/cue_placement.h"
#include "rules/placement.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

std::vector<physics::Ball> scattered() {
  return layout({pocketed(0), resting(2, 0.4, 0.2), resting(4, -0.3, -0.35), resting(7, 0.9, 0.5),
                 resting(8, 0.1, -0.1), resting(11, 0.6, -0.4), resting(13, -0.9, 0.3)});
}

void expectLegal(const PlannedShot& shot, rules::BallInHand in_hand,
                 const std::vector<physics::Ball>& balls) {
  ASSERT_TRUE(shot.cue_ball_at) << describe(shot);
  const auto check = rules::checkCueBallPlacement(in_hand, *shot.cue_ball_at, withoutCueBall(balls),
                                                  nineFoot().context);
  EXPECT_TRUE(check.ok()) << check.error() << " for " << describe(shot);
}

TEST(CuePlacementTest, InHandAnywhereGivesALegalSpotAndAPot) {
  auto state = solidsToShoot();
  state.ball_in_hand = rules::BallInHand::Anywhere;
  const auto balls = scattered();
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, state);
  expectLegal(shot, state.ball_in_hand, balls);
  EXPECT_EQ(shot.kind, ShotKind::Pot) << describe(shot);
}

TEST(CuePlacementTest, BehindTheHeadStringIsStrictlyBehind) {
  auto state = solidsToShoot();
  state.ball_in_hand = rules::BallInHand::BehindHeadString;
  const auto balls = scattered();
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, state);
  expectLegal(shot, state.ball_in_hand, balls);
  EXPECT_LT(shot.cue_ball_at->x(), nineFoot().headStringX());
}

TEST(CuePlacementTest, BallInHandChoiceIsTakenAndPlacedBehindTheHeadString) {
  // After a jumped ball on the break the incoming player may take ball in hand behind the string.
  auto state = solidsToShoot();
  state.phase = rules::Phase::Open;
  state.groups = {rules::Group::None, rules::Group::None};
  state.options = {rules::Choice::PlayOn, rules::Choice::BallInHand};
  const auto balls = scattered();
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(balls, state);
  EXPECT_EQ(shot.choice, rules::Choice::BallInHand);
  expectLegal(shot, rules::BallInHand::BehindHeadString, balls);
}

TEST(CuePlacementTest, ReRackOptionsAreAnsweredWithoutAStroke) {
  auto state = rules::newRack(1);
  state.phase = rules::Phase::Open;
  state.options = {rules::Choice::RespotEight, rules::Choice::ReBreak};
  ShotPlanner planner(nineFoot());
  const PlannedShot shot = planner.plan(scattered(), state);
  EXPECT_EQ(shot.kind, ShotKind::Choice);
  EXPECT_EQ(shot.choice, rules::Choice::ReBreak);
  EXPECT_FALSE(shoots(shot));
}

}  // namespace
}  // namespace pool::bot::test
