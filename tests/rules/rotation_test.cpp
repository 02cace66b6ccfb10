// 9-ball and 10-ball on built logs: the lowest ball first, push-outs, calls, three fouls, the break
// and the rack ball, after the WPA Rules of Play (the World Standardized Rules; sections as
// numbered in the 2008 edition: 2 Nine Ball, 9 Ten Ball, 6 Fouls, 1 General Rules).
#include <gtest/gtest.h>

#include "rules/fixture.h"
#include "rules/game_rules.h"
#include "rules/rotation.h"

namespace pool::rules {
namespace {

using test::ballAt;
using test::LogBuilder;
using test::makeShot;
using test::nineFoot;
using test::spreadLayout;
using test::withPocketed;

const RotationConfig kNine{Rotation::NineBall, 40};
const RotationConfig kTen{Rotation::TenBall, 40};

Verdict judgedRot(const GameState& state, const Shot& shot, const RotationConfig& config) {
  auto verdict = judgeRotation(state, shot, nineFoot(), config);
  EXPECT_TRUE(verdict.hasValue()) << verdict.error();
  return verdict ? *verdict : Verdict{};
}

std::string refusedRot(const GameState& state, const Shot& shot, const RotationConfig& config) {
  auto verdict = judgeRotation(state, shot, nineFoot(), config);
  return verdict ? "" : verdict.error();
}

// After the break, the table open, `shooter` to shoot from where the cue ball lies.
GameState inPlay(int shooter = 0) {
  GameState state = newRack(1 - shooter);
  state.phase = Phase::Open;
  state.shooter = shooter;
  state.ball_in_hand = BallInHand::None;
  return state;
}

// The cue ball's x for a break: behind the head string.
constexpr double kBehind = -0.8;

std::vector<physics::Ball> nineBalls(double cue_x = -0.3) {
  return spreadLayout({1, 2, 3, 4, 5, 6, 7, 8, 9}, cue_x);
}

std::vector<physics::Ball> tenBalls(double cue_x = -0.3) {
  return spreadLayout({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, cue_x);
}

// ---- The break: WPA 2.3 and 9.3 Legal Break Shot (the 1 first; a ball pocketed, or four object
// balls to the rails, else a foul: 1.5 Cue Ball in Hand anywhere), 2.5 Continuing Play (the 9
// pocketed on a legal break wins), 2.6 and 9.7 Spotting Balls (the 9 on a foul, the 10 on the
// break, are spotted). The 10-ball re-rack offered after an illegal break is the game's option, not
// the 2008 text's.

TEST(RotationBreak, BallDownKeepsTheBreakerAndOffersThePushOut) {
  auto balls = nineBalls(kBehind);
  Shot shot =
      makeShot(balls, Intent::none(),
               LogBuilder().hit(0, 1).hit(1, 4).hit(1, 2).cushion(2).pocket(4, "foot_left_corner"));
  Verdict v = judgedRot(newRack(0), shot, kNine);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 0);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PushOut}));
  EXPECT_EQ(v.next.phase, Phase::Open);
}

TEST(RotationBreak, FourCushionsWithoutABallDownPassesTheTurn) {
  auto balls = nineBalls(kBehind);
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder()
                           .hit(0, 1)
                           .hit(1, 2)
                           .hit(1, 3)
                           .hit(2, 5)
                           .hit(3, 6)
                           .cushion(2)
                           .cushion(3)
                           .cushion(5)
                           .cushion(6));
  Verdict v = judgedRot(newRack(0), shot, kNine);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PushOut}));
}

TEST(RotationBreak, IllegalBreakIn9BallIsBallInHandAnywhere) {
  auto balls = nineBalls(kBehind);
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder().hit(0, 1).hit(1, 2).hit(1, 3).cushion(2).cushion(3));
  Verdict v = judgedRot(newRack(0), shot, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::IllegalBreak)) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PushOut}));
  EXPECT_EQ(v.next.fouls_in_row[0], 1);
}

TEST(RotationBreak, IllegalBreakIn10BallOffersAReRack) {
  auto balls = tenBalls(kBehind);
  Shot shot = makeShot(balls, Intent::none(), LogBuilder().hit(0, 1).hit(1, 2).cushion(2));
  Verdict v = judgedRot(newRack(0), shot, kTen);
  EXPECT_TRUE(v.hasFoul(Foul::IllegalBreak)) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.options,
            (std::vector<Choice>{Choice::PlayOn, Choice::ReBreak, Choice::OpponentReBreaks}));
  // Seat 1 has the breaker break again: seat 0 breaks a new rack.
  auto again = applyRotationChoice(v.next, Choice::OpponentReBreaks);
  ASSERT_TRUE(again) << again.error();
  EXPECT_TRUE(again->rerack);
  EXPECT_EQ(again->next.breaker, 0);
  EXPECT_EQ(again->next.phase, Phase::Break);
  // Or seat 1 breaks it; or plays on with the cue ball in hand anywhere.
  auto mine = applyRotationChoice(v.next, Choice::ReBreak);
  ASSERT_TRUE(mine);
  EXPECT_EQ(mine->next.breaker, 1);
  auto on = applyRotationChoice(v.next, Choice::PlayOn);
  ASSERT_TRUE(on);
  EXPECT_FALSE(on->rerack);
  EXPECT_EQ(on->next.shooter, 1);
  EXPECT_EQ(on->next.ball_in_hand, BallInHand::Anywhere);
}

TEST(RotationBreak, MissingTheOneOnTheBreakIsAFoul) {
  auto balls = nineBalls(kBehind);
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder().hit(0, 2).hit(2, 3).cushion(2).pocket(3, "foot_left_corner"));
  Verdict v = judgedRot(newRack(0), shot, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst)) << describe(v);
  EXPECT_FALSE(v.hasFoul(Foul::IllegalBreak));
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(v.pocketed, std::vector<int>{3});  // it stays down
}

TEST(RotationBreak, NineOnALegalBreakWins) {
  auto balls = nineBalls(kBehind);
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder().hit(0, 1).hit(1, 9).pocket(9, "foot_left_corner"));
  Verdict v = judgedRot(newRack(0), shot, kNine);
  EXPECT_TRUE(v.game_over) << describe(v);
  EXPECT_EQ(v.end, GameEnd::RackBallPocketed);
  EXPECT_EQ(v.winner, 0);
  EXPECT_EQ(v.next.phase, Phase::Over);
}

TEST(RotationBreak, NineOnAFoulBreakIsRespotted) {
  auto balls = nineBalls(kBehind);
  Shot shot = makeShot(
      balls, Intent::none(),
      LogBuilder().hit(0, 1).hit(1, 9).pocket(9, "foot_left_corner").pocket(0, "left_side"));
  Verdict v = judgedRot(newRack(0), shot, kNine);
  EXPECT_FALSE(v.game_over) << describe(v);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed));
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 9);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(RotationBreak, TenOnTheBreakIsRespottedAndTheBreakerShootsOn) {
  auto balls = tenBalls(kBehind);
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder().hit(0, 1).hit(1, 10).pocket(10, "foot_left_corner"));
  Verdict v = judgedRot(newRack(0), shot, kTen);
  EXPECT_FALSE(v.game_over) << describe(v);
  EXPECT_TRUE(v.legal());
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 10);
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 0);
}

// ---- Lowest ball first: WPA 6.2 Wrong Ball First (the lowest-numbered ball), 6.3 No Rail after
// Contact, 2.5 Continuing Play (any ball legally pocketed keeps the turn; the 9 wins, on a
// combination too), 2.6 Spotting Balls (the 9 pocketed on a foul or driven off the table is
// spotted, no other ball)

TEST(RotationPlay, LowestBallFirstIsLegalAnyBallDownKeepsTheTurn) {
  auto balls = withPocketed(nineBalls(), {1});
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder().hit(0, 2).hit(2, 5).pocket(5, "foot_right_corner"));
  Verdict v = judgedRot(inPlay(), shot, kNine);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.pocketed, std::vector<int>{5});
  EXPECT_EQ(rotationFirstBalls(balls), std::vector<int>{2});
}

TEST(RotationPlay, HittingAHigherBallFirstIsAFoul) {
  auto balls = withPocketed(nineBalls(), {1});
  Shot shot = makeShot(balls, Intent::none(),
                       LogBuilder().hit(0, 3).cushion(3).pocket(3, "foot_right_corner"));
  Verdict v = judgedRot(inPlay(), shot, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst)) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
  EXPECT_TRUE(v.respots.empty());  // the 3 stays down
}

TEST(RotationPlay, NoCushionAfterContactIsAFoul) {
  auto balls = nineBalls();
  Shot shot = makeShot(balls, Intent::none(), LogBuilder().hit(0, 1).rest(1).rest(0));
  Verdict v = judgedRot(inPlay(), shot, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::NoCushionAfterContact)) << describe(v);
}

TEST(RotationPlay, NineOnAComboWins) {
  auto balls = withPocketed(nineBalls(), {1, 2, 3});
  Shot shot =
      makeShot(balls, Intent::none(), LogBuilder().hit(0, 4).hit(4, 9).pocket(9, "left_side"));
  Verdict v = judgedRot(inPlay(1), shot, kNine);
  EXPECT_TRUE(v.game_over) << describe(v);
  EXPECT_EQ(v.end, GameEnd::RackBallPocketed);
  EXPECT_EQ(v.winner, 1);
}

TEST(RotationPlay, NineOnAFoulIsRespotted) {
  auto balls = withPocketed(nineBalls(), {1, 2, 3});
  Shot shot =
      makeShot(balls, Intent::none(), LogBuilder().hit(0, 5).hit(5, 9).pocket(9, "left_side"));
  Verdict v = judgedRot(inPlay(), shot, kNine);
  EXPECT_FALSE(v.game_over) << describe(v);
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst));
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 9);
}

TEST(RotationPlay, NineOffTheTableIsRespottedOthersStayOff) {
  auto balls = nineBalls();
  Shot shot =
      makeShot(balls, Intent::none(),
               LogBuilder().hit(0, 1).hit(1, 9).airborne(9).offTable(9).airborne(1).offTable(1));
  Verdict v = judgedRot(inPlay(), shot, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::ObjectBallOffTable)) << describe(v);
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 9);
  EXPECT_EQ(v.off_table, (std::vector<int>{9, 1}));
}

// ---- The push-out: WPA 2.4 and 9.4 Second Shot of the Rack – Push Out (6.2 and 6.3 suspended, the
// other player chooses who shoots; only on the shot after the break), 2.6 (the 9 pocketed on a
// push-out is spotted)

TEST(RotationPushOut, ExcusesContactFoulsAndLetsTheOpponentChoose) {
  auto balls = nineBalls();
  GameState after_break = inPlay(1);
  after_break.options = {Choice::PlayOn, Choice::PushOut};
  Intent push;
  push.choice = Choice::PushOut;
  // Hits nothing at all: a foul on an ordinary shot, fine on a push-out.
  Shot shot = makeShot(balls, push, LogBuilder().cushion(0, "head").rest(0));
  Verdict v = judgedRot(after_break, shot, kNine);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.next_shooter, 0);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PassBack}));
  EXPECT_FALSE(v.next.push_out);
  // The opponent passes it back: seat 1 shoots again from where the balls lie.
  auto back = applyRotationChoice(v.next, Choice::PassBack);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->next.shooter, 1);
  EXPECT_EQ(back->next.ball_in_hand, BallInHand::None);
  EXPECT_TRUE(back->next.options.empty());
  // Without the push-out the same shot is a foul.
  Intent play_on;
  play_on.choice = Choice::PlayOn;
  Verdict foul =
      judgedRot(after_break, makeShot(balls, play_on, LogBuilder().cushion(0, "head")), kNine);
  EXPECT_TRUE(foul.hasFoul(Foul::NoBallHit)) << describe(foul);
}

TEST(RotationPushOut, AScratchOnAPushOutIsStillAFoul) {
  auto balls = nineBalls();
  GameState after_break = inPlay(1);
  after_break.options = {Choice::PlayOn, Choice::PushOut};
  auto chosen = applyRotationChoice(after_break, Choice::PushOut);
  ASSERT_TRUE(chosen);
  EXPECT_TRUE(chosen->next.push_out);
  Shot shot = makeShot(balls, Intent::none(), LogBuilder().pocket(0, "head_left_corner"));
  Verdict v = judgedRot(chosen->next, shot, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed)) << describe(v);
  EXPECT_TRUE(v.options.empty());
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(RotationPushOut, NineOnAPushOutIsRespotted) {
  auto balls = nineBalls();
  GameState st = inPlay(1);
  st.push_out = true;
  Shot shot = makeShot(balls, Intent::none(), LogBuilder().hit(0, 9).pocket(9, "foot_left_corner"));
  Verdict v = judgedRot(st, shot, kNine);
  EXPECT_FALSE(v.game_over) << describe(v);
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 9);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PassBack}));
}

TEST(RotationPushOut, OnlyOfferedAfterTheBreak) {
  auto balls = nineBalls();
  Intent push;
  push.choice = Choice::PushOut;
  EXPECT_EQ(refusedRot(inPlay(), makeShot(balls, push, LogBuilder().hit(0, 1).cushion(1)), kNine),
            "no choice is pending");
  GameState st = inPlay();
  EXPECT_FALSE(applyRotationChoice(st, Choice::PushOut));
}

// ---- Three fouls: WPA 6.14 Three Consecutive Fouls and 2.8 Serious Fouls (the rack is lost); a
// legal shot ends the run; 6.15 Slow Play (the shot clock's time-out is a foul)

TEST(RotationFouls, TheThirdFoulInARowLosesTheRack) {
  auto balls = nineBalls();
  GameState st = inPlay(0);
  st.fouls_in_row = {2, 1};
  Shot miss = makeShot(balls, Intent::none(), LogBuilder().cushion(0, "foot"));
  Verdict v = judgedRot(st, miss, kNine);
  EXPECT_TRUE(v.game_over) << describe(v);
  EXPECT_EQ(v.end, GameEnd::ThreeFouls);
  EXPECT_EQ(v.winner, 1);
  EXPECT_EQ(v.next.phase, Phase::Over);
}

TEST(RotationFouls, ALegalShotClearsTheCount) {
  auto balls = nineBalls();
  GameState st = inPlay(0);
  st.fouls_in_row = {2, 1};
  Verdict v =
      judgedRot(st, makeShot(balls, Intent::none(), LogBuilder().hit(0, 1).cushion(1)), kNine);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.next.fouls_in_row[0], 0);
  EXPECT_EQ(v.next.fouls_in_row[1], 1);  // the opponent's count stands
  // A second foul only counts up.
  st.fouls_in_row = {1, 0};
  Verdict second =
      judgedRot(st, makeShot(balls, Intent::none(), LogBuilder().hit(0, 2).cushion(2)), kNine);
  EXPECT_FALSE(second.game_over);
  EXPECT_EQ(second.next.fouls_in_row[0], 2);
}

TEST(RotationFouls, ATimeOutCountsAsAFoul) {
  auto balls = nineBalls();
  GameState st = inPlay(0);
  st.fouls_in_row = {2, 0};
  Shot none;
  none.before = balls;
  none.after = balls;
  none.clock_expired = true;
  Verdict v = judgedRot(st, none, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::ShotClockExpired));
  EXPECT_EQ(v.end, GameEnd::ThreeFouls);
  st.fouls_in_row = {0, 0};
  Verdict first = judgedRot(st, none, kNine);
  EXPECT_EQ(first.next_shooter, 1);
  EXPECT_EQ(first.ball_in_hand, BallInHand::Anywhere);
}

// ---- 10-ball calls: WPA 9.5 Shots Required to Be Called (1.6 Standard Call Shot: one ball and
// pocket; a ball pocketed otherwise lets the incoming player choose who shoots; a safety may be
// called), 9.6 Continuing Play (the 10 called wins), 9.7 Spotting Balls (the 10 not called is
// spotted)

TEST(TenBallCalls, TheCalledBallInTheCalledPocketKeepsTheTurn) {
  auto balls = tenBalls();
  Shot shot = makeShot(balls, Intent::call(1, "foot_left_corner"),
                       LogBuilder().hit(0, 1).pocket(1, "foot_left_corner"));
  Verdict v = judgedRot(inPlay(), shot, kTen);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_TRUE(v.turn_continues);
  EXPECT_TRUE(v.options.empty());
}

TEST(TenBallCalls, AnotherPocketPassesTheTurnWithAChoice) {
  auto balls = tenBalls();
  Shot shot = makeShot(balls, Intent::call(1, "foot_left_corner"),
                       LogBuilder().hit(0, 1).pocket(1, "left_side"));
  Verdict v = judgedRot(inPlay(), shot, kTen);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.pocketed, std::vector<int>{1});  // it stays down
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PassBack}));
}

TEST(TenBallCalls, TheTenCalledWinsTheTenUncalledIsRespotted) {
  auto balls = withPocketed(tenBalls(), {1, 2});
  Shot called = makeShot(balls, Intent::call(10, "right_side"),
                         LogBuilder().hit(0, 3).hit(3, 10).pocket(10, "right_side"));
  Verdict win = judgedRot(inPlay(), called, kTen);
  EXPECT_TRUE(win.game_over) << describe(win);
  EXPECT_EQ(win.end, GameEnd::RackBallPocketed);
  EXPECT_EQ(win.winner, 0);

  Shot uncalled = makeShot(balls, Intent::call(3, "foot_left_corner"),
                           LogBuilder().hit(0, 3).hit(3, 10).pocket(10, "right_side"));
  Verdict v = judgedRot(inPlay(), uncalled, kTen);
  EXPECT_FALSE(v.game_over) << describe(v);
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 10);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PassBack}));
}

TEST(TenBallCalls, ASafetyPassesTheTurnWhateverFalls) {
  auto balls = tenBalls();
  Shot shot = makeShot(balls, Intent::safe(), LogBuilder().hit(0, 1).pocket(1, "left_side"));
  Verdict v = judgedRot(inPlay(), shot, kTen);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_TRUE(v.options.empty());
}

TEST(TenBallCalls, ShotsAfterTheBreakMustBeCalled) {
  auto balls = tenBalls();
  Shot shot = makeShot(balls, Intent::none(), LogBuilder().hit(0, 1).cushion(1));
  EXPECT_EQ(refusedRot(inPlay(), shot, kTen), "call a ball and a pocket, or declare a safety");
  EXPECT_EQ(
      refusedRot(inPlay(), makeShot(balls, Intent::call(11, "left_side"), LogBuilder()), kTen),
      "called ball 11 is not in this game");
  EXPECT_EQ(refusedRot(inPlay(), makeShot(balls, Intent::call(2, "middle"), LogBuilder()), kTen),
            "unknown called pocket 'middle'");
  // 9-ball needs none.
  EXPECT_EQ(
      refusedRot(inPlay(), makeShot(nineBalls(), Intent::none(), LogBuilder().hit(0, 1).cushion(1)),
                 kNine),
      "");
}

// ---- The one entry by game (no rule: the dispatch to each game's rules) -------------------------

TEST(GameRules, DispatchesByGame) {
  EXPECT_EQ(gameOfNumber(9), Game::NineBall);
  EXPECT_EQ(gameOfNumber(10), Game::TenBall);
  EXPECT_EQ(gameOfNumber(8), Game::EightBall);
  EXPECT_FALSE(gameOfNumber(7));
  EXPECT_EQ(rackTypeOf(Game::TenBall), table::RackType::TenBall);
  auto balls = withPocketed(tenBalls(), {1});
  GameRules ten{Game::TenBall, {}, {}};
  EXPECT_EQ(firstBallsFor(ten, inPlay(), balls), std::vector<int>{2});
  // 8-ball on the same open table lets any ball but the 8 be hit first.
  GameRules eight{Game::EightBall, {}, {}};
  EXPECT_GT(firstBallsFor(eight, inPlay(), balls).size(), 5u);
  Shot shot = makeShot(balls, Intent::none(), LogBuilder().hit(0, 2).cushion(2));
  EXPECT_FALSE(judgeShot(ten, inPlay(), shot, nineFoot()));  // 10-ball: a call is needed
}

}  // namespace
}  // namespace pool::rules
