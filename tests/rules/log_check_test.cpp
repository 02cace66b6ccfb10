// Bad input: event logs and final balls that contradict themselves are refused, never judged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rules/eight_ball.h"
#include "rules/fixture.h"
#include "rules/log_check.h"
#include "rules/practice.h"

namespace pool::rules {
namespace {

using physics::EventType;
using test::LogBuilder;
using test::makeShot;
using test::spreadLayout;

const std::vector<int> kAll = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

// The reason a shot of `log` on the spread layout is refused by the referee.
std::string refused(const LogBuilder& log) {
  Shot shot = makeShot(spreadLayout(kAll), Intent::call(3, "left_side"), log);
  std::string why = test::refusal(test::assigned(), shot);
  auto practice = judgePractice(shot, test::nineFoot());
  EXPECT_EQ(practice ? "" : practice.error(), why) << "practice must refuse the same log";
  return why;
}

physics::Event eventAt(double t, EventType type, int a, int b = -1, std::string where = "") {
  physics::Event e;
  e.t = t;
  e.type = type;
  e.ball_a = a;
  e.ball_b = b;
  e.where = std::move(where);
  return e;
}

TEST(BadInput, ABallPocketedTwice) {
  auto why = refused(LogBuilder().hit(0, 3).pocket(3, "left_side").pocket(3, "right_side"));
  EXPECT_NE(why.find("ball 3"), std::string::npos) << why;
}

TEST(BadInput, AnEventAfterEveryBallCameToRest) {
  auto why = refused(LogBuilder().hit(0, 3).rest(3).rest(0).cushion(3));
  EXPECT_NE(why.find("rest"), std::string::npos) << why;
}

TEST(BadInput, ASpinEndingAfterRestIsFine) {
  LogBuilder log;
  log.hit(0, 3).cushion(3).rest(3).rest(0).raw(eventAt(9.0, EventType::SpinToRest, 0));
  EXPECT_EQ(refused(log), "");
}

TEST(BadInput, EventsOutOfTimeOrder) {
  LogBuilder log;
  log.hit(0, 3).raw(eventAt(0.01, EventType::BallCushion, 3, -1, "foot"));
  auto why = refused(log);
  EXPECT_NE(why.find("order"), std::string::npos) << why;
}

TEST(BadInput, TimeNotFinite) {
  LogBuilder log;
  log.raw(eventAt(std::numeric_limits<double>::quiet_NaN(), EventType::BallBall, 0, 3));
  EXPECT_NE(refused(log), "");
}

TEST(BadInput, AnUnknownBallId) {
  EXPECT_NE(refused(LogBuilder().hit(0, 16)).find("unknown ball 16"), std::string::npos);
  EXPECT_NE(refused(LogBuilder().hit(0, -3)).find("unknown"), std::string::npos);
  Shot shot = makeShot(test::withPocketed(spreadLayout(kAll), {5}), Intent::call(3, "left_side"),
                       LogBuilder().hit(0, 5));
  auto why = test::refusal(test::assigned(), shot);
  EXPECT_NE(why.find("not on the table"), std::string::npos) << why;
}

TEST(BadInput, APocketedBallLaterHittingSomething) {
  auto why = refused(LogBuilder().hit(0, 3).pocket(3, "left_side").hit(0, 3));
  EXPECT_NE(why.find("pocketed"), std::string::npos) << why;
  EXPECT_NE(refused(LogBuilder().hit(0, 3).pocket(3, "left_side").cushion(3)), "");
  EXPECT_NE(refused(LogBuilder().hit(0, 3).offTable(3).hit(0, 3)), "");
}

TEST(BadInput, NoStrikeFirstOrASecondStrike) {
  LogBuilder log;
  log.raw(eventAt(0.1, EventType::Strike, 0));
  EXPECT_NE(refused(log).find("second strike"), std::string::npos);
  Shot shot = makeShot(spreadLayout(kAll), Intent::call(3, "left_side"), LogBuilder());
  shot.events.front().type = EventType::BallBall;
  shot.events.front().ball_b = 3;
  EXPECT_NE(test::refusal(test::assigned(), shot).find("strike"), std::string::npos);
}

TEST(BadInput, AnEmptyLogWithoutATimeOut) {
  Shot shot = makeShot(spreadLayout(kAll), Intent::call(3, "left_side"), LogBuilder());
  shot.events.clear();
  EXPECT_NE(test::refusal(test::assigned(), shot).find("empty"), std::string::npos);
}

TEST(BadInput, AnUnknownPocket) {
  EXPECT_NE(refused(LogBuilder().hit(0, 3).pocket(3, "kitchen_sink")).find("pocket"),
            std::string::npos);
}

TEST(BadInput, MotionWithoutACause) {
  EXPECT_NE(refused(LogBuilder().hit(0, 3).cushion(5)).find("without being set in motion"),
            std::string::npos);
  EXPECT_NE(refused(LogBuilder().hit(0, 3).rest(3).rest(0).hit(3, 5)), "");
  EXPECT_NE(refused(LogBuilder().hit(0, 3).hit(5, 6)).find("at rest"), std::string::npos);
  EXPECT_NE(refused(LogBuilder().hit(0, 0)).find("itself"), std::string::npos);
}

TEST(BadInput, FinalBallsDisagreeWithTheLog) {
  Shot shot =
      makeShot(spreadLayout(kAll), Intent::call(3, "left_side"), LogBuilder().hit(0, 3).cushion(3));
  shot.after[3].state = physics::MotionState::Pocketed;
  EXPECT_NE(test::refusal(test::assigned(), shot).find("never"), std::string::npos);
  Shot dropped = makeShot(spreadLayout(kAll), Intent::call(3, "left_side"),
                          LogBuilder().hit(0, 3).pocket(3, "left_side"));
  dropped.after = dropped.before;
  EXPECT_NE(test::refusal(test::assigned(), dropped), "");
  Shot missing =
      makeShot(spreadLayout(kAll), Intent::call(3, "left_side"), LogBuilder().hit(0, 3).cushion(3));
  missing.after.pop_back();
  EXPECT_NE(test::refusal(test::assigned(), missing).find("missing"), std::string::npos);
}

TEST(BadInput, BallsBeforeRepeatAnId) {
  Shot shot =
      makeShot(spreadLayout(kAll), Intent::call(3, "left_side"), LogBuilder().hit(0, 3).cushion(3));
  shot.before.push_back(test::ballAt(4, 0.0, 0.5));
  EXPECT_NE(checkShot(shot).error().find("twice"), std::string::npos);
}

TEST(BadInput, AWatchdogRemovalExcusesTheFinalState) {
  Shot shot = makeShot(spreadLayout(kAll), Intent::call(3, "left_side"),
                       LogBuilder().hit(0, 3).cushion(3).hit(3, 12).respot(12));
  shot.after[12].state = physics::MotionState::OffTable;
  EXPECT_TRUE(checkShot(shot)) << checkShot(shot).error();
  Verdict v = test::judged(test::assigned(), shot);
  ASSERT_EQ(v.respots.size(), 1u);  // no foul: the ball goes back
  EXPECT_EQ(v.respots[0].id, 12);
  EXPECT_TRUE(v.legal());
}

}  // namespace
}  // namespace pool::rules
