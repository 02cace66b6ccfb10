// 8-ball's end after the WPA Rules of Play (the World Standardized Rules; sections as numbered
// since the 2008 edition): winning on the 8, 3.8 Losing the Rack, 1.12 and 3.11 Stalemate, 1.11
// Concession.
#include <gtest/gtest.h>

#include "rules/eight_ball.h"
#include "rules/fixture.h"

namespace pool::rules {
namespace {

using test::assigned;
using test::judged;
using test::LogBuilder;
using test::makeShot;
using test::openTable;
using test::spreadLayout;

// Seat 0 (solids) has cleared the group: the 8 and three stripes remain.
std::vector<physics::Ball> onTheEight() {
  return spreadLayout({8, 9, 10, 11});
}

// WPA Eight Ball (the section's opening) and 1.6 Standard Call Shot: the 8, called, pocketed once
// the group is off the table wins the rack.
TEST(Eight, PocketedInTheCalledPocketWins) {
  Verdict v = judged(assigned(), makeShot(onTheEight(), Intent::call(8, "foot_left_corner"),
                                          LogBuilder().hit(0, 8).pocket(8, "foot_left_corner")));
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.winner, 0);
  EXPECT_EQ(v.end, GameEnd::EightPocketed);
  EXPECT_EQ(v.next.phase, Phase::Over);
  EXPECT_EQ(v.next.winner, 0);
  auto again = judgeEightBall(
      v.next, makeShot(onTheEight(), Intent::call(8, "left_side"), LogBuilder().hit(0, 8)),
      test::nineFoot());
  EXPECT_FALSE(again);  // nothing is judged after the game
}

// WPA 3.8 Losing the Rack: a foul when pocketing the 8.
TEST(Eight, EightAndCueBallFallingTogetherLoses) {
  LogBuilder log;
  log.hit(0, 8).pocket(8, "foot_left_corner").pocket(0, "foot_right_corner");
  Verdict v = judged(assigned(), makeShot(onTheEight(), Intent::call(8, "foot_left_corner"), log));
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.winner, 1);
  EXPECT_EQ(v.end, GameEnd::EightOnFoul);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed));
}

// WPA 3.8 Losing the Rack: the 8 pocketed when it is not the legal object ball.
TEST(Eight, PocketedBeforeTheGroupIsClearedLoses) {
  auto balls = spreadLayout({3, 8, 9, 10});
  Verdict v = judged(assigned(),
                     makeShot(balls, Intent::call(3, "left_side"),
                              LogBuilder().hit(0, 3).hit(3, 8).pocket(8, "right_side").cushion(3)));
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.end, GameEnd::EightBeforeGroupCleared);
  EXPECT_EQ(v.winner, 1);
}

// WPA 3.8 Losing the Rack: the 8 pocketed when it is not the legal object ball (3.4: on an open
// table it never is).
TEST(Eight, PocketedOnAnOpenTableLoses) {
  auto balls = spreadLayout({1, 2, 3, 8, 9, 10});
  Verdict v =
      judged(openTable(1), makeShot(balls, Intent::call(3, "left_side"),
                                    LogBuilder().hit(0, 3).hit(3, 8).pocket(8, "right_side")));
  EXPECT_EQ(v.end, GameEnd::EightBeforeGroupCleared);
  EXPECT_EQ(v.winner, 0);
}

// WPA 3.8 Losing the Rack: the 8 pocketed on the same stroke as the last ball of the group.
TEST(Eight, ClearingTheGroupAndTheEightOnOneShotLoses) {
  auto balls = spreadLayout({7, 8, 9, 10});
  LogBuilder log;
  log.hit(0, 7).hit(7, 8).pocket(7, "left_side").pocket(8, "foot_left_corner");
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(7, "left_side"), log));
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.end, GameEnd::EightWithLastGroupBall);
  EXPECT_EQ(v.winner, 1);
}

// WPA 3.8 Losing the Rack: the 8 pocketed in a pocket other than the one called.
TEST(Eight, WrongPocketLoses) {
  Verdict v = judged(assigned(), makeShot(onTheEight(), Intent::call(8, "foot_left_corner"),
                                          LogBuilder().hit(0, 8).pocket(8, "left_side")));
  EXPECT_EQ(v.end, GameEnd::EightWrongPocket);
  EXPECT_EQ(v.winner, 1);
}

// WPA 3.8 Losing the Rack: a safety calls no pocket, so the 8 falls in one not called.
TEST(Eight, PocketedOnASafetyLoses) {
  Verdict v = judged(assigned(), makeShot(onTheEight(), Intent::safe(),
                                          LogBuilder().hit(0, 8).pocket(8, "left_side")));
  EXPECT_EQ(v.end, GameEnd::EightWrongPocket);
}

// WPA 3.8 Losing the Rack: the 8 driven off the table (after the break; on it, 3.3 (g) spots it).
TEST(Eight, OffTheTableAfterTheBreakLoses) {
  auto balls = spreadLayout({3, 8, 9});
  Verdict v =
      judged(assigned(1), makeShot(balls, Intent::call(9, "left_side"),
                                   LogBuilder().hit(0, 9).hit(9, 8).airborne(8).offTable(8)));
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.end, GameEnd::EightOffTable);
  EXPECT_EQ(v.winner, 0);
  EXPECT_TRUE(v.respots.empty());
}

// WPA 3.8 lists only fouls that pocket the 8 or drive it off: any other is a standard foul, cue
// ball in hand anywhere (1.5 Cue Ball in Hand).
TEST(Eight, AFoulOnTheEightWithoutPocketingItIsNoLoss) {
  Verdict v =
      judged(assigned(), makeShot(onTheEight(), Intent::call(8, "foot_left_corner"),
                                  LogBuilder().hit(0, 8).cushion(8).pocket(0, "left_side")));
  EXPECT_FALSE(v.game_over);
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::CueBallPocketed});
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

// WPA 1.12 Stalemate (three more turns each without progress) and 3.11: the original breaker of the
// rack breaks again.
TEST(Stalemate, LackOfProgressReRacksWithTheSameBreaker) {
  EightBallConfig config;
  config.stalemate_turns = 3;
  GameState state = assigned();
  state.breaker = 1;
  auto balls = spreadLayout({1, 2, 8, 9, 10});
  Verdict v;
  for (int shot = 0; shot < 3; ++shot) {
    int shooter = state.shooter;
    int own = shooter == 0 ? 1 : 9;
    v = judged(
        state,
        makeShot(balls, Intent::call(own, "left_side"), LogBuilder().hit(0, own).cushion(own)),
        config);
    state = v.next;
  }
  EXPECT_TRUE(v.rerack);
  EXPECT_TRUE(v.stalemate);
  EXPECT_EQ(v.next.phase, Phase::Break);
  EXPECT_EQ(v.next.breaker, 1);
  EXPECT_EQ(v.next.shooter, 1);
}

// WPA 1.12 Stalemate: the turns count while no progress is made; a ball pocketed is progress.
TEST(Stalemate, ABallDownResetsTheCount) {
  EightBallConfig config;
  config.stalemate_turns = 2;
  GameState state = assigned();
  state.dry_turns = 1;
  auto balls = spreadLayout({1, 2, 8, 9, 10});
  Verdict v = judged(
      state,
      makeShot(balls, Intent::call(1, "left_side"), LogBuilder().hit(0, 1).pocket(1, "left_side")),
      config);
  EXPECT_FALSE(v.rerack);
  EXPECT_EQ(v.next.dry_turns, 0);
}

// WPA 1.12 Stalemate: both players may accept the stalemate without their further turns; 3.11: the
// original breaker breaks again.
TEST(Stalemate, ByAgreement) {
  GameState state = assigned(1);
  state.breaker = 0;
  auto v = agreeStalemate(state);
  ASSERT_TRUE(v);
  EXPECT_TRUE(v->rerack);
  EXPECT_TRUE(v->stalemate);
  EXPECT_EQ(v->next.breaker, 0);
  EXPECT_EQ(v->next.ball_in_hand, BallInHand::BehindHeadString);
}

// WPA 1.11 Concession: a player who concedes loses.
TEST(Forfeit, TheOtherSeatWins) {
  Verdict v = forfeit(assigned(), 0);
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.winner, 1);
  EXPECT_EQ(v.end, GameEnd::Forfeit);
  EXPECT_EQ(v.next.phase, Phase::Over);
}

// Not a rule: the names the logs and the protocol use.
TEST(Names, EnumsHaveNames) {
  EXPECT_STREQ(toString(Foul::NoCushionAfterContact), "no_cushion_after_contact");
  EXPECT_STREQ(toString(GameEnd::EightWithLastGroupBall), "eight_with_last_group_ball");
  EXPECT_STREQ(toString(Choice::RespotEight), "respot_eight");
  EXPECT_STREQ(toString(BallInHand::BehindHeadString), "behind_head_string");
  EXPECT_STREQ(toString(Phase::Assigned), "assigned");
  EXPECT_STREQ(toString(Group::Stripes), "stripes");
  EXPECT_STREQ(toString(CallMode::Casual), "casual");
  Verdict v = judged(assigned(), makeShot(onTheEight(), Intent::call(8, "foot_left_corner"),
                                          LogBuilder().hit(0, 8).pocket(8, "foot_left_corner")));
  EXPECT_NE(describe(v).find("eight_pocketed"), std::string::npos) << describe(v);
}

}  // namespace
}  // namespace pool::rules
