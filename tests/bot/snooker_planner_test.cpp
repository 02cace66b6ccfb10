// The bot's snooker: the break-off from the D, a pot at a colour nominated, a free ball taken.
#include <gtest/gtest.h>

#include "client/bot/ai/planned_shot.h"
#include "client/bot/ai/shot_planner.h"
#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/table_view.h"
#include "rules/game_rules.h"
#include "table/rack.h"

namespace pool::bot {
namespace {

const TableView& snookerView() {
  static const TableView view = [] {
    auto loaded = loadTableView("snooker-12ft");
    EXPECT_TRUE(loaded) << loaded.error();
    TableView v = std::move(*loaded);
    v.rules.game = rules::Game::Snooker;
    return v;
  }();
  return view;
}

std::vector<physics::Ball> frameOpening(std::uint64_t seed) {
  std::vector<physics::Ball> balls;
  for (const auto& p : table::rackFor(table::RackType::Snooker, snookerView().spec,
                                      snookerView().radius(), seed, table::RackGenerator::Hand)) {
    balls.push_back(physics::restingBall(p.id, p.pos, snookerView().radius()));
  }
  return balls;
}

TEST(SnookerPlanner, TheBreakOffIsLegalFromTheDAndComesBackUpTheTable) {
  // Official Rules of Snooker, Section 3, "Playing from in-Hand" and "Play": the break-off is
  // played from the D and must hit a red first. Played exactly, the bot's break-off is legal on
  // each of five hand racks and leaves the cue ball behind the blue (x < 0), as a safe break-off
  // does.
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    ShotPlanner planner(snookerView(), PlannerOptions{});
    const auto balls = frameOpening(seed);
    const rules::GameState state = rules::newRackOf(rules::Game::Snooker, 0);
    const PlannedShot shot = planner.plan(balls, state);
    ASSERT_TRUE(shot.cue_ball_at) << describe(shot);
    EXPECT_TRUE(table::inTheD(*snookerView().context.snooker, *shot.cue_ball_at));
    ShotVerifier verifier(snookerView());
    const Trial t = verifier.run(balls, state, shot);
    ASSERT_TRUE(t.judged) << t.error;
    EXPECT_TRUE(t.verdict.legal()) << seed << ": " << rules::describe(t.verdict);
    EXPECT_LT(t.cue_end.x(), 0.0) << seed << ": the cue ball stayed up the table";
  }
}

TEST(SnookerPlanner, OnAColourItNominatesTheColourItPots) {
  // No reds left in the way: the black 0.4 m in front of a top pocket, the cue ball behind it.
  const TableView& v = snookerView();
  const double r = v.radius();
  std::vector<physics::Ball> balls{physics::restingBall(0, {0.9, 0.3}, r),
                                   physics::restingBall(1, {-0.5, -0.6}, r)};
  for (int c = table::kSnookerYellow; c <= table::kSnookerBlack; ++c) {
    balls.push_back(physics::restingBall(c, *table::snookerSpotOf(v.spec, c), r));
  }
  rules::GameState state = rules::newRackOf(rules::Game::Snooker, 0);
  state.phase = rules::Phase::Open;
  state.ball_in_hand = rules::BallInHand::None;
  state.ball_on = rules::kOnColour;
  ShotPlanner planner(v, PlannerOptions{});
  const PlannedShot shot = planner.plan(balls, state);
  ASSERT_EQ(shot.kind, ShotKind::Pot) << describe(shot);
  const rules::Intent intent = intentOf(shot);
  ASSERT_TRUE(intent.ball) << describe(shot);
  EXPECT_TRUE(rules::isColour(*intent.ball));
  EXPECT_TRUE(intent.pocket.empty());  // snooker calls no pocket
  EXPECT_FALSE(intent.safety);
  ShotVerifier verifier(v);
  const Trial t = verifier.run(balls, state, shot);
  ASSERT_TRUE(t.judged) << t.error;
  EXPECT_TRUE(t.verdict.legal()) << rules::describe(t.verdict);
  EXPECT_EQ(t.verdict.scored, rules::snookerValue(*intent.ball)) << rules::describe(t.verdict);
}

TEST(SnookerPlanner, ItTakesAFreeBallWhenOffered) {
  EXPECT_EQ(chooseOption({rules::Choice::PlayOn, rules::Choice::FreeBall, rules::Choice::PassBack,
                          rules::Choice::Replace}),
            rules::Choice::FreeBall);
  // Snookered behind the green with the last red far away: no pot as the table lies, yet the
  // planner takes the free ball rather than handing the table back.
  const TableView& v = snookerView();
  const double r = v.radius();
  const Eigen::Vector2d green = *table::snookerSpotOf(v.spec, table::kSnookerGreen);
  std::vector<physics::Ball> balls{physics::restingBall(0, green - Eigen::Vector2d(0.1, 0.0), r),
                                   physics::restingBall(1, {1.5, green.y()}, r)};
  for (int c = table::kSnookerYellow; c <= table::kSnookerBlack; ++c) {
    balls.push_back(physics::restingBall(c, *table::snookerSpotOf(v.spec, c), r));
  }
  rules::GameState state = rules::newRackOf(rules::Game::Snooker, 0);
  state.phase = rules::Phase::Open;
  state.ball_in_hand = rules::BallInHand::None;
  state.options = {rules::Choice::PlayOn, rules::Choice::FreeBall, rules::Choice::PassBack};
  ShotPlanner planner(v, PlannerOptions{});
  const PlannedShot shot = planner.plan(balls, state);
  ASSERT_TRUE(shot.choice) << describe(shot);
  EXPECT_EQ(*shot.choice, rules::Choice::FreeBall) << describe(shot);
  EXPECT_TRUE(shoots(shot));
}

}  // namespace
}  // namespace pool::bot
