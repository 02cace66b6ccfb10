// Distilling an event log into a referee's facts.
#include <gtest/gtest.h>

#include "rules/fixture.h"
#include "rules/shot_facts.h"

namespace pool::rules {
namespace {

using test::LogBuilder;
using test::makeShot;

ShotFacts factsOf(const LogBuilder& log,
                  std::vector<physics::Ball> balls = test::spreadLayout({1, 2, 3, 9, 10})) {
  auto shot = makeShot(balls, Intent::none(), log);
  auto facts = distilShot(shot, test::nineFoot().spots.head_string_x);
  EXPECT_TRUE(facts) << facts.error();
  return facts ? *facts : ShotFacts{};
}

TEST(ShotFacts, FirstContactWithTheCueBallOnEitherSide) {
  LogBuilder log;
  log.raw([] {
    physics::Event e;
    e.t = 0.1;
    e.type = physics::EventType::BallBall;
    e.ball_a = 9;
    e.ball_b = 0;
    return e;
  }());
  log.hit(9, 2).hit(0, 3);
  ShotFacts f = factsOf(log);
  EXPECT_EQ(f.first_contact, 9);
}

TEST(ShotFacts, CushionsCountOnlyFromTheFirstContact) {
  ShotFacts before = factsOf(LogBuilder().cushion(0, "head").hit(0, 1));
  EXPECT_FALSE(before.cushion_after_contact);
  ShotFacts after = factsOf(LogBuilder().hit(0, 1).cushion(1, "jaw_left_side"));
  EXPECT_TRUE(after.cushion_after_contact);
  EXPECT_EQ(after.cushioned, std::vector<int>{1});
}

TEST(ShotFacts, PocketsAndBallsOffTheTable) {
  ShotFacts f = factsOf(LogBuilder()
                            .hit(0, 1)
                            .hit(1, 10)
                            .pocket(10, "right_side")
                            .airborne(1)
                            .offTable(1)
                            .pocket(0, "left_side"));
  EXPECT_EQ(f.objectBallsPocketed(), std::vector<int>{10});
  EXPECT_EQ(f.objectBallsOffTable(), std::vector<int>{1});
  EXPECT_EQ(f.pocketOf(10), "right_side");
  EXPECT_EQ(f.pocketOf(2), "");
  EXPECT_TRUE(f.cueBallLost());
}

TEST(ShotFacts, CueBallCrossingTheHeadString) {
  // Ball 1 lies behind the head string, as does the cue ball.
  std::vector<physics::Ball> kitchen{test::ballAt(0, -1.0, 0.0), test::ballAt(1, -0.9, 0.3)};
  EXPECT_FALSE(
      factsOf(LogBuilder().cushion(0, "head", -1.2).hit(0, 1), kitchen).cue_crossed_head_string);
  EXPECT_TRUE(
      factsOf(LogBuilder().cushion(0, "foot", 1.2).hit(0, 1), kitchen).cue_crossed_head_string);
  // Hitting a ball past the string, the cue ball itself is past it at the contact.
  EXPECT_TRUE(factsOf(LogBuilder().hit(0, 2)).cue_crossed_head_string);
}

}  // namespace
}  // namespace pool::rules
