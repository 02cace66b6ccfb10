// 8-ball after the break, after the WPA Rules of Play (the World Standardized Rules; sections as
// numbered since the 2008 edition): kitchen play, the open table, calls and safeties, legal shots,
// continuing play, fouls. Casual calls are the game's own variant, cited as such.
#include <gtest/gtest.h>

#include "rules/eight_ball.h"
#include "rules/fixture.h"

namespace pool::rules {
namespace {

using test::assigned;
using test::ballAt;
using test::judged;
using test::LogBuilder;
using test::makeShot;
using test::openTable;
using test::spreadLayout;

const std::vector<int> kAll = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

// --- Ball in hand behind the head string: WPA 1.5 Cue Ball in Hand, 6.11 Bad Play from Behind
// the Head String (a ball behind the string may not be hit without the cue ball first crossing it)

// A scratch on the break left the cue ball in hand behind the head string; ball 3 lies behind it
// too.
struct Kitchen {
  GameState state = [] {
    GameState s = openTable(1);
    s.ball_in_hand = BallInHand::BehindHeadString;
    return s;
  }();
  std::vector<physics::Ball> balls = [] {
    auto b = spreadLayout({1, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}, -1.0);
    b.push_back(ballAt(3, -0.9, 0.3));
    return b;
  }();
};

TEST(Kitchen, BallBehindTheHeadStringMayNotBePlayedDirectly) {
  Kitchen k;
  Verdict v = judged(k.state, makeShot(k.balls, Intent::call(3, "head_left_corner"),
                                       LogBuilder().hit(0, 3).pocket(3, "head_left_corner")));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::BehindHeadStringDirect});
  EXPECT_EQ(v.next_shooter, 0);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(v.next.groups[1], Group::None);
}

TEST(Kitchen, CrossingTheHeadStringFirstMakesItLegal) {
  Kitchen k;
  LogBuilder log;
  log.cushion(0, "foot", 1.24).hit(0, 3).pocket(3, "head_left_corner");
  Verdict v = judged(k.state, makeShot(k.balls, Intent::call(3, "head_left_corner"), log));
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.assigned, Group::Solids);
}

TEST(Kitchen, BallsPastTheHeadStringArePlayable) {
  Kitchen k;
  Verdict v = judged(k.state, makeShot(k.balls, Intent::call(1, "foot_left_corner"),
                                       LogBuilder().hit(0, 1).pocket(1, "foot_left_corner")));
  EXPECT_TRUE(v.legal());
}

// --- The open table: WPA 3.4 Open Table / Choosing Groups (any ball but the 8 first; the group
// is the called ball's, legally pocketed), 6.2 Wrong Ball First

TEST(OpenTable, AnyBallButTheEightMayBeHitFirst) {
  auto balls = spreadLayout(kAll);
  // A stripe first, to pocket the called solid: legal, and the shooter takes solids.
  Verdict v = judged(openTable(),
                     makeShot(balls, Intent::call(3, "foot_left_corner"),
                              LogBuilder().hit(0, 10).hit(10, 3).pocket(3, "foot_left_corner")));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.assigned, Group::Solids);
  EXPECT_EQ(v.next.phase, Phase::Assigned);
  EXPECT_EQ(v.next.groups[0], Group::Solids);
  EXPECT_EQ(v.next.groups[1], Group::Stripes);
}

TEST(OpenTable, EightFirstIsAFoul) {
  auto balls = spreadLayout(kAll);
  Verdict v =
      judged(openTable(), makeShot(balls, Intent::call(3, "foot_left_corner"),
                                   LogBuilder().hit(0, 8).hit(8, 3).pocket(3, "foot_left_corner")));
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst));
  EXPECT_EQ(v.assigned, Group::None);
  EXPECT_EQ(v.next.phase, Phase::Open);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(OpenTable, GroupNeedsTheCalledBallLegallyPocketed) {
  auto balls = spreadLayout(kAll);
  // The called 3 misses; the 11 falls: no group, the turn passes, no foul.
  Verdict v =
      judged(openTable(), makeShot(balls, Intent::call(3, "foot_left_corner"),
                                   LogBuilder().hit(0, 3).hit(3, 11).pocket(11, "right_side")));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.assigned, Group::None);
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.pocketed, std::vector<int>{11});
  EXPECT_EQ(v.next.phase, Phase::Open);
}

TEST(OpenTable, NoGroupOnAFoul) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(
      openTable(),
      makeShot(balls, Intent::call(3, "foot_left_corner"),
               LogBuilder().hit(0, 3).pocket(3, "foot_left_corner").pocket(0, "right_side")));
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed));
  EXPECT_EQ(v.assigned, Group::None);
  EXPECT_EQ(v.next.phase, Phase::Open);
}

// --- Calls and safeties: WPA 1.6 Standard Call Shot and 8-ball's Shots Required to Be Called
// (every shot after the break, one ball and pocket; a called safety passes the turn and what it
// pockets stays down). Casual: the game's own variant, only the 8's pocket called.

TEST(Calls, EveryShotAfterTheBreakIsCalled) {
  auto balls = spreadLayout(kAll);
  auto why = test::refusal(openTable(),
                           makeShot(balls, Intent::none(), LogBuilder().hit(0, 3).cushion(3)));
  EXPECT_NE(why.find("call"), std::string::npos) << why;
}

TEST(Calls, CalledBallMustBeTheShootersAndThePocketReal) {
  auto balls = spreadLayout(kAll);
  LogBuilder log;
  log.hit(0, 3).cushion(3);
  EXPECT_NE(test::refusal(assigned(), makeShot(balls, Intent::call(12, "left_side"), log)), "");
  EXPECT_NE(test::refusal(assigned(), makeShot(balls, Intent::call(8, "left_side"), log)), "");
  EXPECT_NE(test::refusal(openTable(), makeShot(balls, Intent::call(8, "left_side"), log)), "");
  EXPECT_NE(test::refusal(assigned(), makeShot(balls, Intent::call(3, "middle"), log)), "");
  EXPECT_NE(test::refusal(assigned(), makeShot(test::withPocketed(balls, {3}),
                                               Intent::call(3, "left_side"), log)),
            "");
  Intent both = Intent::call(3, "left_side");
  both.safety = true;
  EXPECT_NE(test::refusal(assigned(), makeShot(balls, both, log)), "");
  EXPECT_EQ(test::refusal(assigned(), makeShot(balls, Intent::call(3, "left_side"), log)), "");
}

TEST(Calls, SafetyBallsStayDownAndTheTurnPasses) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(openTable(), makeShot(balls, Intent::safe(),
                                           LogBuilder().hit(0, 3).pocket(3, "foot_left_corner")));
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.pocketed, std::vector<int>{3});
  EXPECT_EQ(v.assigned, Group::None);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
}

TEST(Calls, ASafetyMustStillBeALegalShot) {
  auto balls = spreadLayout(kAll);
  Verdict v =
      judged(assigned(), makeShot(balls, Intent::safe(), LogBuilder().hit(0, 3).rest(3).rest(0)));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::NoCushionAfterContact});
}

TEST(Calls, CalledBallInAnotherPocketIsAMiss) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(3, "foot_left_corner"),
                                          LogBuilder().hit(0, 3).pocket(3, "left_side")));
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
}

TEST(Casual, OnlyTheEightIsCalled) {
  EightBallConfig casual;
  casual.calls = CallMode::Casual;
  auto balls = spreadLayout(kAll);
  Verdict v = judged(
      assigned(),
      makeShot(balls, Intent::none(), LogBuilder().hit(0, 3).hit(3, 5).pocket(5, "left_side")),
      casual);
  EXPECT_TRUE(v.turn_continues);
  Verdict open = judged(
      openTable(), makeShot(balls, Intent::none(), LogBuilder().hit(0, 12).pocket(12, "left_side")),
      casual);
  EXPECT_EQ(open.assigned, Group::Stripes);
  // An opponent's ball alone does not keep the turn.
  Verdict other = judged(
      assigned(),
      makeShot(balls, Intent::none(), LogBuilder().hit(0, 3).hit(3, 12).pocket(12, "left_side")),
      casual);
  EXPECT_FALSE(other.turn_continues);
  // On the 8 the pocket must be called.
  auto on_eight = spreadLayout({8, 9, 10});
  auto why = test::refusal(
      assigned(), makeShot(on_eight, Intent::none(), LogBuilder().hit(0, 8).cushion(8)), casual);
  EXPECT_NE(why.find("8"), std::string::npos) << why;
}

// --- A legal shot: WPA 6.2 Wrong Ball First (8-ball: a ball of the shooter's group, or the 8 once
// the group is cleared) and 6.3 No Rail after Contact

TEST(LegalShot, WrongGroupFirstIsAFoul) {
  auto balls = spreadLayout(kAll);
  Verdict v =
      judged(assigned(), makeShot(balls, Intent::call(3, "left_side"),
                                  LogBuilder().hit(0, 12).hit(12, 3).pocket(3, "left_side")));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::WrongBallFirst});
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.pocketed, std::vector<int>{3});
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(LegalShot, NoBallHitIsAFoul) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(
      assigned(), makeShot(balls, Intent::call(3, "left_side"), LogBuilder().cushion(0).rest(0)));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::NoBallHit});
}

TEST(LegalShot, NoCushionAfterContactIsAFoul) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(3, "left_side"),
                                          LogBuilder().hit(0, 3).rest(0).rest(3)));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::NoCushionAfterContact});
}

TEST(LegalShot, ABankBeforeTheFirstContactDoesNotCount) {
  auto balls = spreadLayout(kAll);
  LogBuilder bank;
  bank.cushion(0, "head").hit(0, 3).rest(0).rest(3);
  EXPECT_EQ(judged(assigned(), makeShot(balls, Intent::call(3, "left_side"), bank)).fouls,
            std::vector<Foul>{Foul::NoCushionAfterContact});
  LogBuilder bank_then_rail;
  bank_then_rail.cushion(0, "head").hit(0, 3).cushion(3, "foot");
  EXPECT_TRUE(
      judged(assigned(), makeShot(balls, Intent::call(3, "left_side"), bank_then_rail)).legal());
}

TEST(LegalShot, CueBallToACushionAfterContactIsEnough) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(3, "left_side"),
                                          LogBuilder().hit(0, 3).cushion(0, "foot_left")));
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.turn_continues);
}

TEST(LegalShot, OnceClearedTheEightMustBeHitFirst) {
  auto balls = spreadLayout({8, 9, 10, 11});
  Verdict v = judged(
      assigned(), makeShot(balls, Intent::call(8, "left_side"), LogBuilder().hit(0, 9).cushion(9)));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::WrongBallFirst});
  EXPECT_FALSE(v.game_over);
}

// --- Continuing play: WPA 8-ball's Continuing Play and Shots Required to Be Called (the called
// ball in its pocket keeps the turn; other balls pocketed stay down; combinations are allowed)

TEST(Scoring, CalledBallPocketedKeepsTheTurn) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(3, "left_side"),
                                          LogBuilder().hit(0, 3).pocket(3, "left_side")));
  EXPECT_TRUE(v.legal());
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.next.shooter, 0);
  EXPECT_EQ(v.next.ball_in_hand, BallInHand::None);
}

TEST(Scoring, SlopStaysDownWithoutAFoul) {
  auto balls = spreadLayout(kAll);
  LogBuilder log;
  log.hit(0, 3).hit(3, 12).pocket(3, "left_side").pocket(12, "foot_right_corner");
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(3, "left_side"), log));
  EXPECT_TRUE(v.legal());
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.pocketed, (std::vector<int>{3, 12}));
  EXPECT_TRUE(v.respots.empty());
}

TEST(Scoring, SlopOnAnOpenTableGivesTheCalledGroup) {
  auto balls = spreadLayout(kAll);
  LogBuilder log;
  log.hit(0, 12).hit(12, 3).pocket(12, "right_side").pocket(3, "left_side");
  Verdict v = judged(openTable(), makeShot(balls, Intent::call(3, "left_side"), log));
  EXPECT_EQ(v.assigned, Group::Solids);
}

TEST(Scoring, AMissPassesTheTurnWithoutAFoul) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(
      assigned(), makeShot(balls, Intent::call(3, "left_side"), LogBuilder().hit(0, 3).cushion(3)));
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
}

TEST(Scoring, CombinationShot) {
  auto balls = spreadLayout(kAll);
  LogBuilder log;
  log.hit(0, 2).hit(2, 10).hit(10, 5).pocket(5, "foot_left_corner");
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(5, "foot_left_corner"), log));
  EXPECT_TRUE(v.legal());
  EXPECT_TRUE(v.turn_continues);
}

// --- Fouls: WPA 6.1 Cue Ball Scratch or off the Table, 6.5 Ball Driven off the Table (it stays
// off; 1.4 Spotting Balls spots only the 8), 6.15 Slow Play (the shot clock), with 1.5 Cue Ball in
// Hand anywhere for the incoming player

TEST(Fouls, ObjectBallPocketedThenCueBallScratch) {
  auto balls = spreadLayout(kAll);
  LogBuilder log;
  log.hit(0, 3).pocket(3, "left_side").pocket(0, "foot_left_corner");
  Verdict v = judged(assigned(), makeShot(balls, Intent::call(3, "left_side"), log));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::CueBallPocketed});
  EXPECT_EQ(v.pocketed, std::vector<int>{3});  // stays down
  EXPECT_TRUE(v.respots.empty());
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(Fouls, CueBallOffTheTable) {
  auto balls = spreadLayout(kAll);
  Verdict v =
      judged(assigned(), makeShot(balls, Intent::call(3, "left_side"),
                                  LogBuilder().hit(0, 3).cushion(3).airborne(0).offTable(0)));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::CueBallOffTable});
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(Fouls, ABallJumpingOffTheTableStaysOff) {
  auto balls = spreadLayout(kAll);
  Verdict v = judged(
      assigned(), makeShot(balls, Intent::call(3, "left_side"),
                           LogBuilder().hit(0, 3).hit(3, 11).airborne(11).offTable(11).cushion(3)));
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::ObjectBallOffTable});
  EXPECT_EQ(v.off_table, std::vector<int>{11});
  EXPECT_TRUE(v.respots.empty());
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(Fouls, ShotClockExpiry) {
  auto balls = spreadLayout(kAll);
  Shot late;
  late.before = balls;
  late.intent = Intent::call(3, "left_side");
  late.clock_expired = true;
  Verdict v = judged(assigned(), late);
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::ShotClockExpired});
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);

  Shot struck_late =
      makeShot(balls, Intent::call(3, "left_side"), LogBuilder().hit(0, 3).pocket(3, "left_side"));
  struck_late.clock_expired = true;
  Verdict w = judged(assigned(), struck_late);
  EXPECT_EQ(w.fouls, std::vector<Foul>{Foul::ShotClockExpired});
  EXPECT_FALSE(w.turn_continues);
}

TEST(Fouls, ShotClockOnTheBreakHandsTheBreakOver) {
  Shot late;
  late.before = test::rackLayout();
  late.clock_expired = true;
  Verdict v = judged(newRack(0), late);
  EXPECT_TRUE(v.hasFoul(Foul::ShotClockExpired));
  EXPECT_EQ(v.next.phase, Phase::Break);
  EXPECT_EQ(v.next.breaker, 1);
}

TEST(Fouls, BallInHandAnywhereIsCheckedOnTheSlate) {
  GameState state = assigned();
  state.ball_in_hand = BallInHand::Anywhere;
  auto balls = spreadLayout(kAll);
  balls[0].pos = balls[1].pos;  // on top of another ball
  EXPECT_NE(test::refusal(state, makeShot(balls, Intent::call(3, "left_side"),
                                          LogBuilder().hit(0, 3).cushion(3))),
            "");
}

}  // namespace
}  // namespace pool::rules
