// The bot in 9-ball and 10-ball: it aims at the lowest ball, calls in 10-ball, pushes out when the
// lowest ball has no pot, and hands a poor table back after a push-out.
#include <gtest/gtest.h>

#include <cmath>

#include "client/bot/ai/shot_planner.h"
#include "client/bot/ai/shot_verifier.h"
#include "rules/game_rules.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

TableView viewOf(rules::Game game) {
  TableView view = nineFoot();
  view.rules.game = game;
  return view;
}

rules::GameState openTable(std::vector<rules::Choice> options = {}) {
  rules::GameState state = rules::newRack(1);
  state.phase = rules::Phase::Open;
  state.shooter = 0;
  state.ball_in_hand = rules::BallInHand::None;
  state.options = std::move(options);
  return state;
}

// The 1 straight in front of the foot left corner pocket, the cue ball behind it, the 2 and the
// rack ball elsewhere.
std::vector<physics::Ball> oneStraightIn(int rack_ball) {
  const Vec2 object = onPocketLine("foot_left_corner", Vec2::Zero(), 0.6);
  const Vec2 cue = onPocketLine("foot_left_corner", Vec2::Zero(), 1.2);
  return layout({resting(0, cue.x(), cue.y()), resting(1, object.x(), object.y()),
                 resting(2, -0.8, -0.4), resting(rack_ball, 0.9, -0.45)});
}

// The 1 boxed in by four balls: no pot line for it from anywhere.
std::vector<physics::Ball> oneBoxedIn(int rack_ball) {
  const double d = 2.1 * nineFoot().radius();
  return layout({resting(0, -0.8, 0.3), resting(1, 0.3, 0.0), resting(2, 0.3 + d, 0.0),
                 resting(3, 0.3, d), resting(4, 0.3 - d, 0.0), resting(5, 0.3, -d),
                 resting(rack_ball, 0.9, -0.45)});
}

TEST(RotationPlanner, TenBallCallsTheLowestBallAndPotsIt) {
  const TableView view = viewOf(rules::Game::TenBall);
  const auto balls = oneStraightIn(10);
  ShotPlanner planner(view);
  const PlannedShot shot = planner.plan(balls, openTable());
  ASSERT_EQ(shot.kind, ShotKind::Pot) << describe(shot);
  EXPECT_EQ(shot.called_ball, 1);
  EXPECT_EQ(shot.called_pocket, "foot_left_corner");
  ShotVerifier verifier(view);
  const Trial trial = verifier.run(balls, openTable(), shot);
  ASSERT_TRUE(trial.judged) << trial.error;
  EXPECT_TRUE(trial.verdict.legal()) << rules::describe(trial.verdict);
  EXPECT_TRUE(trial.verdict.turn_continues);
}

TEST(RotationPlanner, NineBallNeverHitsAnEasierHigherBallFirst) {
  // The 5 hangs in a pocket's mouth; the 2 is the lowest ball and must be hit first.
  const Vec2 five = onPocketLine("foot_right_corner", Vec2::Zero(), 0.15);
  const TableView view = viewOf(rules::Game::NineBall);
  const auto balls = layout({resting(0, -0.3, 0.1), resting(2, -0.9, -0.5),
                             resting(5, five.x(), five.y()), resting(9, 0.6, 0.45)});
  ShotPlanner planner(view);
  const PlannedShot shot = planner.plan(balls, openTable());
  ShotVerifier verifier(view);
  const Trial trial = verifier.run(balls, openTable(), shot);
  ASSERT_TRUE(trial.judged) << trial.error;
  EXPECT_FALSE(trial.verdict.hasFoul(rules::Foul::WrongBallFirst)) << describe(shot);
}

TEST(RotationPlanner, PushesOutOnlyWhenTheLowestBallHasNoPot) {
  const TableView view = viewOf(rules::Game::NineBall);
  const auto options = std::vector<rules::Choice>{rules::Choice::PlayOn, rules::Choice::PushOut};
  ShotPlanner planner(view);
  const PlannedShot boxed = planner.plan(oneBoxedIn(9), openTable(options));
  ASSERT_TRUE(boxed.choice);
  EXPECT_EQ(*boxed.choice, rules::Choice::PushOut) << describe(boxed);
  EXPECT_TRUE(shoots(boxed));
  // The push-out the bot plays is legal: the opponent then chooses.
  ShotVerifier verifier(view);
  const Trial pushed = verifier.run(oneBoxedIn(9), openTable(options), boxed);
  ASSERT_TRUE(pushed.judged) << pushed.error;
  EXPECT_TRUE(pushed.verdict.legal()) << rules::describe(pushed.verdict);
  EXPECT_EQ(pushed.verdict.options,
            (std::vector<rules::Choice>{rules::Choice::PlayOn, rules::Choice::PassBack}));

  const PlannedShot open = planner.plan(oneStraightIn(9), openTable(options));
  ASSERT_TRUE(open.choice);
  EXPECT_EQ(*open.choice, rules::Choice::PlayOn) << describe(open);
  EXPECT_EQ(open.kind, ShotKind::Pot);
}

TEST(RotationPlanner, HandsAPoorTableBackAndPlaysAGoodOne) {
  const TableView view = viewOf(rules::Game::TenBall);
  const auto options = std::vector<rules::Choice>{rules::Choice::PlayOn, rules::Choice::PassBack};
  ShotPlanner planner(view);
  const PlannedShot poor = planner.plan(oneBoxedIn(10), openTable(options));
  ASSERT_TRUE(poor.choice);
  EXPECT_EQ(*poor.choice, rules::Choice::PassBack);
  EXPECT_FALSE(shoots(poor));
  const PlannedShot good = planner.plan(oneStraightIn(10), openTable(options));
  ASSERT_TRUE(good.choice);
  EXPECT_EQ(*good.choice, rules::Choice::PlayOn);
  EXPECT_EQ(good.kind, ShotKind::Pot);
  EXPECT_EQ(good.called_ball, 1);
}

}  // namespace
}  // namespace pool::bot::test
