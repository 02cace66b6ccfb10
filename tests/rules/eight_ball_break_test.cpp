// 8-ball's break after the WPA Rules of Play (the World Standardized Rules; sections as numbered
// since the 2008 edition): 3.3 Break Shot, with 1.5 Cue Ball in Hand and 1.4 Spotting Balls.
#include <gtest/gtest.h>

#include "rules/eight_ball.h"
#include "rules/fixture.h"
#include "table/rack.h"

namespace pool::rules {
namespace {

using test::LogBuilder;
using test::makeShot;
using test::rackLayout;

// The cue ball opens the rack and four balls (2, 3, 4, 5) reach a cushion.
LogBuilder fourCushionBreak() {
  LogBuilder log;
  log.hit(0, 1).hit(1, 2).hit(1, 3).hit(2, 4).hit(3, 5);
  log.cushion(2, "foot_left").cushion(3, "foot_right").cushion(4, "foot").cushion(5, "head_left");
  return log;
}

Verdict breakWith(const LogBuilder& log) {
  return test::judged(newRack(0), makeShot(rackLayout(), Intent::none(), log));
}

// WPA 3.3 (c): a ball pocketed without a foul keeps the breaker at the table; the table stays open.
TEST(Break, BallPocketedIsLegalAndBreakerContinues) {
  LogBuilder log;
  log.hit(0, 1).hit(1, 2).pocket(2, "foot_left_corner");
  Verdict v = breakWith(log);
  EXPECT_TRUE(v.legal());
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 0);
  EXPECT_EQ(v.pocketed, std::vector<int>{2});
  EXPECT_EQ(v.next.phase, Phase::Open);
  EXPECT_EQ(v.next.groups[0], Group::None);  // WPA 3.3 (c): the table stays open
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
}

// WPA 3.3 (d): without a ball pocketed, four object balls driven to one or more rails make the
// break legal.
TEST(Break, FourBallsToACushionIsLegalAndTheTurnPasses) {
  Verdict v = breakWith(fourCushionBreak());
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
  EXPECT_TRUE(v.options.empty());
  EXPECT_EQ(v.next.phase, Phase::Open);
}

// WPA 3.3 (d): "four object balls" to the rails: four distinct balls (a pocket's jaws are cushion).
TEST(Break, JawsCountAsCushionsAndABallCountsOnce) {
  LogBuilder log;
  log.hit(0, 1).hit(1, 2).hit(1, 3).hit(2, 4);
  log.cushion(2, "foot")
      .cushion(2, "foot_left")
      .cushion(3, "jaw_foot_left_corner")
      .cushion(4, "foot_right");
  EXPECT_TRUE(breakWith(log).hasFoul(Foul::IllegalBreak));  // three distinct balls
  log.hit(4, 6).cushion(6, "jaw_right_side");
  EXPECT_TRUE(breakWith(log).legal());
}

// WPA 3.3 (d) (1)-(3): after an illegal break the incoming player accepts the table, re-racks and
// breaks, or has the breaker break again.
TEST(Break, IllegalBreakOffersPlayOnReRackOrBreakerBreaksAgain) {
  LogBuilder log;
  log.hit(0, 1).hit(1, 2).hit(1, 3).cushion(2).cushion(3).cushion(0, "foot", 1.2);
  Verdict v = breakWith(log);
  EXPECT_TRUE(v.hasFoul(Foul::IllegalBreak));
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::None);
  EXPECT_EQ(v.options,
            (std::vector<Choice>{Choice::PlayOn, Choice::ReBreak, Choice::OpponentReBreaks}));
  EXPECT_EQ(v.next.options, v.options);
  EXPECT_EQ(v.next.shooter, 1);
}

// WPA 3.3 (d) (1)-(3), each option applied.
TEST(Break, IllegalBreakChoices) {
  GameState offered = breakWith(LogBuilder().hit(0, 1)).next;
  auto table = test::nineFoot();
  auto balls = rackLayout();

  auto play_on = applyChoice(offered, Choice::PlayOn, balls, table);
  ASSERT_TRUE(play_on) << play_on.error();
  EXPECT_FALSE(play_on->rerack);
  EXPECT_EQ(play_on->next.shooter, 1);
  EXPECT_EQ(play_on->next.phase, Phase::Open);
  EXPECT_TRUE(play_on->next.options.empty());

  auto self = applyChoice(offered, Choice::ReBreak, balls, table);
  ASSERT_TRUE(self);
  EXPECT_TRUE(self->rerack);
  EXPECT_EQ(self->next.phase, Phase::Break);
  EXPECT_EQ(self->next.breaker, 1);
  EXPECT_EQ(self->next.ball_in_hand, BallInHand::BehindHeadString);

  auto again = applyChoice(offered, Choice::OpponentReBreaks, balls, table);
  ASSERT_TRUE(again);
  EXPECT_TRUE(again->rerack);
  EXPECT_EQ(again->next.breaker, 0);
  EXPECT_EQ(again->next.shooter, 0);

  EXPECT_FALSE(applyChoice(offered, Choice::RespotEight, balls, table));
}

// WPA 3.3 (d) (1): accepting the table in position is shown by playing it.
TEST(Break, PlayOnCanBeGivenWithTheShot) {
  GameState offered = breakWith(LogBuilder().hit(0, 1)).next;
  auto balls = rackLayout();
  Intent intent = Intent::call(3, "foot_left_corner");
  EXPECT_NE(test::refusal(offered, makeShot(balls, intent, LogBuilder().hit(0, 3).cushion(3))), "");
  intent.choice = Choice::PlayOn;
  Verdict v = test::judged(offered, makeShot(balls, intent, LogBuilder().hit(0, 3).cushion(3)));
  EXPECT_TRUE(v.legal());
  intent.choice = Choice::ReBreak;
  EXPECT_NE(test::refusal(offered, makeShot(balls, intent, LogBuilder().hit(0, 3).cushion(3))), "");
}

// WPA 3.3 (a): the cue ball begins in hand behind the head string (on the string is not behind
// it).
TEST(Break, TakenFromBehindTheHeadString) {
  auto balls = rackLayout();
  balls[0].pos.x() = test::nineFoot().spots.head_string_x;  // on the string is not behind it
  auto why = test::refusal(newRack(0), makeShot(balls, Intent::none(), fourCushionBreak()));
  EXPECT_NE(why.find("head string"), std::string::npos) << why;
}

// WPA 3.3 (h): a scratch on a legal break is a foul; balls pocketed stay down and the
// incoming player has the cue ball in hand behind the head string.
TEST(Break, ScratchOnALegalBreak) {
  LogBuilder log = fourCushionBreak();
  log.pocket(2, "foot_left_corner").pocket(0, "head_right_corner");
  Verdict v = breakWith(log);
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::CueBallPocketed});
  EXPECT_EQ(v.pocketed, std::vector<int>{2});  // stays down
  EXPECT_TRUE(v.respots.empty());
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::BehindHeadString);
  EXPECT_TRUE(v.options.empty());
  EXPECT_EQ(v.next.phase, Phase::Open);
}

// WPA 3.3 (h) and 6.1 Cue Ball Scratch or off the Table: as a scratch.
TEST(Break, CueBallOffTheTableOnTheBreak) {
  LogBuilder log = fourCushionBreak();
  log.hit(0, 6).offTable(0);
  Verdict v = breakWith(log);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallOffTable));
  EXPECT_EQ(v.ball_in_hand, BallInHand::BehindHeadString);
  EXPECT_EQ(v.next_shooter, 1);
}

// WPA 3.3 (g): an object ball jumped off the table on the break is a foul and is not
// spotted; the incoming player accepts the table or takes the cue ball in hand behind the head
// string.
TEST(Break, ObjectBallJumpedOffTheTable) {
  LogBuilder log = fourCushionBreak();
  log.airborne(4).offTable(4);
  Verdict v = breakWith(log);
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::ObjectBallOffTable});
  EXPECT_EQ(v.off_table, std::vector<int>{4});
  EXPECT_TRUE(v.respots.empty());  // it stays off
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::BallInHand}));

  auto table = test::nineFoot();
  auto after = test::applyLog(rackLayout(), log.build());
  auto as_lies = applyChoice(v.next, Choice::PlayOn, after, table);
  ASSERT_TRUE(as_lies);
  EXPECT_EQ(as_lies->next.ball_in_hand, BallInHand::None);
  auto in_hand = applyChoice(v.next, Choice::BallInHand, after, table);
  ASSERT_TRUE(in_hand);
  EXPECT_EQ(in_hand->next.ball_in_hand, BallInHand::BehindHeadString);
  EXPECT_EQ(in_hand->next.shooter, 1);
}

// WPA 3.3 (g) and 1.5 Cue Ball in Hand: that ball in hand is behind the head string.
TEST(Break, BallInHandChosenWithTheShotMustBeBehindTheHeadString) {
  LogBuilder log = fourCushionBreak();
  log.airborne(4).offTable(4);
  GameState offered = breakWith(log).next;
  auto after = test::applyLog(rackLayout(), log.build());
  Intent intent = Intent::call(3, "foot_left_corner");
  intent.choice = Choice::BallInHand;
  after[0].pos = physics::Vec3(-0.2, 0.3, test::kR);  // in front of the head string
  auto why = test::refusal(offered, makeShot(after, intent, LogBuilder().hit(0, 3).cushion(3)));
  EXPECT_NE(why.find("head string"), std::string::npos) << why;
  after[0].pos = physics::Vec3(-0.9, 0.3, test::kR);
  EXPECT_EQ(test::refusal(offered, makeShot(after, intent, LogBuilder().hit(0, 3).cushion(3))), "");
}

// WPA 3.3 (e): the 8 pocketed on a legal break is no foul; the breaker re-spots it (1.4 Spotting
// Balls) and plays on, or breaks again.
TEST(Break, EightPocketedIsNeitherWinNorLoss) {
  LogBuilder log = fourCushionBreak();
  log.hit(5, 8).pocket(8, "foot_right_corner");
  Verdict v = breakWith(log);
  EXPECT_FALSE(v.game_over);
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.next_shooter, 0);  // the breaker chooses
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::RespotEight, Choice::ReBreak}));

  auto table = test::nineFoot();
  auto after = test::applyLog(rackLayout(), log.build());
  auto respot = applyChoice(v.next, Choice::RespotEight, after, table);
  ASSERT_TRUE(respot) << respot.error();
  ASSERT_EQ(respot->respots.size(), 1u);
  EXPECT_EQ(respot->respots[0].id, 8);
  std::vector<Eigen::Vector2d> occupied;
  for (const auto& b : after) {
    if (physics::onTable(b.state)) occupied.push_back(b.pos.head<2>());
  }
  EXPECT_TRUE(
      respot->respots[0].pos.isApprox(table::respotPosition(table.spec, test::kR, occupied)));
  EXPECT_EQ(respot->next.shooter, 0);
  EXPECT_EQ(respot->next.ball_in_hand, BallInHand::None);

  auto rebreak = applyChoice(v.next, Choice::ReBreak, after, table);
  ASSERT_TRUE(rebreak);
  EXPECT_TRUE(rebreak->rerack);
  EXPECT_EQ(rebreak->next.breaker, 0);
}

// WPA 3.3 (f): the 8 pocketed with a scratch: the opponent re-spots it and shoots with the cue ball
// in hand behind the head string, or breaks again.
TEST(Break, EightAndCueBallScratchOnTheBreak) {
  LogBuilder log = fourCushionBreak();
  log.hit(5, 8).pocket(8, "foot_right_corner").pocket(0, "head_left_corner");
  Verdict v = breakWith(log);
  EXPECT_FALSE(v.game_over);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed));
  EXPECT_EQ(v.next_shooter, 1);  // the incoming player chooses
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::RespotEight, Choice::ReBreak}));

  auto table = test::nineFoot();
  auto after = test::applyLog(rackLayout(), log.build());
  auto respot = applyChoice(v.next, Choice::RespotEight, after, table);
  ASSERT_TRUE(respot);
  EXPECT_EQ(respot->next.shooter, 1);
  EXPECT_EQ(respot->next.ball_in_hand, BallInHand::BehindHeadString);
  auto rebreak = applyChoice(v.next, Choice::ReBreak, after, table);
  ASSERT_TRUE(rebreak);
  EXPECT_EQ(rebreak->next.breaker, 1);
}

// WPA 3.3 (g): the 8 driven off the table on the break is a foul and is spotted (1.4
// Spotting Balls).
TEST(Break, EightJumpedOffOnTheBreakIsRespotted) {
  LogBuilder log = fourCushionBreak();
  log.hit(5, 8).airborne(8).offTable(8);
  Verdict v = breakWith(log);
  EXPECT_FALSE(v.game_over);
  EXPECT_TRUE(v.hasFoul(Foul::ObjectBallOffTable));
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 8);
}

}  // namespace
}  // namespace pool::rules
