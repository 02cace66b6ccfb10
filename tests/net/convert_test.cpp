// Conversions between wire and domain types round-trip exactly and reject what cannot be held.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "net/convert.h"
#include "net/wire_fields.h"
#include "net_fixture.h"

namespace pool::net {
namespace {

using namespace protocol;

using test::oddBall;

/// Bitwise equality of doubles (so -0.0 and 0.0 differ, NaN equals the same NaN).
bool same(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSameBall(const physics::Ball& a, const physics::Ball& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.state, b.state);
  EXPECT_EQ(a.pocket, b.pocket);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(same(a.pos[i], b.pos[i]));
    EXPECT_TRUE(same(a.vel[i], b.vel[i]));
    EXPECT_TRUE(same(a.ang_vel[i], b.ang_vel[i]));
  }
  EXPECT_TRUE(same(a.orient.w(), b.orient.w()));
  EXPECT_TRUE(same(a.orient.x(), b.orient.x()));
  EXPECT_TRUE(same(a.orient.y(), b.orient.y()));
  EXPECT_TRUE(same(a.orient.z(), b.orient.z()));
}

TEST(Convert, BallRoundTripsExactlyInEveryState) {
  for (int s = 0; s <= static_cast<int>(physics::MotionState::OffTable); ++s) {
    physics::Ball ball = oddBall(s + 3);
    ball.state = static_cast<physics::MotionState>(s);
    ball.pocket = ball.state == physics::MotionState::Pocketed ? "foot_left_corner" : "";
    const auto back = fromWire(toWire(ball));
    ASSERT_TRUE(back) << back.error();
    expectSameBall(ball, *back);
  }
}

TEST(Convert, BallFromWireRejectsBadIdAndState) {
  pool_BallState b = toWire(oddBall(1));
  b.id = 22;
  EXPECT_FALSE(fromWire(b));
  b.id = 1;
  setRawValue(b.state, 99);
  EXPECT_FALSE(fromWire(b));
}

TEST(Convert, EventRoundTripsExactlyForEveryType) {
  for (int t = 0; t <= static_cast<int>(physics::EventType::Respot); ++t) {
    physics::Event e;
    e.t = 1.0 / 3.0 + t;
    e.type = static_cast<physics::EventType>(t);
    e.ball_a = t % 16;
    e.ball_b = e.type == physics::EventType::BallBall ? 15 : -1;
    e.where = e.type == physics::EventType::Respot ? "inside another ball" : "jaw_foot_left_corner";
    e.speed = 2.0 / 3.0;
    e.pos = {-1.0 / 9.0, 0.5, 0.028575};
    const auto back = fromWire(toWire(e));
    ASSERT_TRUE(back) << back.error();
    EXPECT_TRUE(same(back->t, e.t));
    EXPECT_EQ(back->type, e.type);
    EXPECT_EQ(back->ball_a, e.ball_a);
    EXPECT_EQ(back->ball_b, e.ball_b);
    EXPECT_EQ(back->where, e.where);
    EXPECT_TRUE(same(back->speed, e.speed));
    EXPECT_EQ(back->pos, e.pos);
  }
}

TEST(Convert, EventFromWireRejectsUnknownType) {
  pool_ShotEvent e = toWire(physics::Event{});
  setRawValue(e.type, 200);
  const auto back = fromWire(e);
  ASSERT_FALSE(back);
  EXPECT_NE(back.error().find("event type"), std::string::npos);
}

// Since protocol version 7 a sequence holds a snooker set, 22 balls (pool.idl's MAX_BALLS).
TEST(Convert, BallSequencesHoldTwentyTwoAndSayWhenCut) {
  std::vector<physics::Ball> balls;
  for (int id = 0; id < 16; ++id) balls.push_back(oddBall(id));
  for (int id = 0; id < 6; ++id) balls.push_back(oddBall(id));  // ids repeat: only the count
  Sample<pool_TableSnapshot> snapshot;
  EXPECT_TRUE(putBalls(snapshot->balls, balls));
  const auto back = getBalls(snapshot->balls);
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->size(), balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) expectSameBall(balls[i], (*back)[i]);

  balls.push_back(oddBall(3));
  EXPECT_FALSE(putBalls(snapshot->balls, balls));  // replaces the buffer: no leak under ASan
  EXPECT_EQ(snapshot->balls._length, 22u);
}

TEST(Convert, EventSequencesNameTheBadIndex) {
  Sample<pool_ShotResult> result;
  physics::EventLog log(3);
  ASSERT_TRUE(putEvents(result->events, log));
  setRawValue(result->events._buffer[2].type, 77);
  const auto back = getEvents(result->events);
  ASSERT_FALSE(back);
  EXPECT_EQ(back.error().rfind("events[2]", 0), 0u) << back.error();
}

ShotRequest fullRequest() {
  ShotRequest r;
  r.match = "srv1-7";
  r.seat = 1;
  r.seat_token = 0xfedcba9876543210ull;
  r.seq = 4'000'000'000u;
  r.cue = {1.0 / 3.0, 0.1, -0.2, 0.3, 5.5, true};
  r.called_ball = 8;
  r.called_pocket = "left_side";
  r.safety = false;
  r.cue_ball_at = Eigen::Vector2d(-0.6, 0.25);
  r.option = ShotOption::RespotEight;
  r.signature = std::vector<std::uint8_t>(64, 0xab);
  return r;
}

TEST(Convert, ShotRequestRoundTrips) {
  const ShotRequest r = fullRequest();
  const auto wire = toWire(r);
  const auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->match, r.match);
  EXPECT_EQ(back->seat, r.seat);
  EXPECT_EQ(back->seat_token, r.seat_token);
  EXPECT_EQ(back->seq, r.seq);
  EXPECT_TRUE(same(back->cue.yaw, r.cue.yaw));
  EXPECT_EQ(back->cue.tip_side, r.cue.tip_side);
  EXPECT_EQ(back->cue.tip_height, r.cue.tip_height);
  EXPECT_EQ(back->cue.elevation, r.cue.elevation);
  EXPECT_EQ(back->cue.speed, r.cue.speed);
  EXPECT_EQ(back->cue.speed_is_ball, r.cue.speed_is_ball);
  EXPECT_EQ(back->called_ball, r.called_ball);
  EXPECT_EQ(back->called_pocket, r.called_pocket);
  EXPECT_EQ(back->safety, r.safety);
  EXPECT_EQ(back->cue_ball_at, r.cue_ball_at);
  EXPECT_EQ(back->option, r.option);
  EXPECT_EQ(back->signature, r.signature);
}

TEST(Convert, ShotRequestWithoutOptionalsRoundTrips) {
  ShotRequest r;
  r.match = "m";
  r.cue.speed = 1.0;
  const auto back = fromWire(*toWire(r));
  ASSERT_TRUE(back) << back.error();
  EXPECT_FALSE(back->called_ball);
  EXPECT_FALSE(back->cue_ball_at);
  EXPECT_TRUE(back->signature.empty());
  EXPECT_EQ(back->option, ShotOption::None);
}

TEST(Convert, EveryShotOptionRoundTrips) {
  for (int o = 0; o <= static_cast<int>(ShotOption::OpponentReBreaks); ++o) {
    const auto option = static_cast<ShotOption>(o);
    const auto back = fromWire(toWire(option));
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, option) << toString(option);
  }
  pool_ShotOption bad{};
  setRawValue(bad, 42);
  EXPECT_FALSE(fromWire(bad));
}

TEST(Convert, TextTooLongIsCutNotOverrun) {
  ShotRequest r = fullRequest();
  r.match = std::string(100, 'x');
  const auto wire = toWire(r);
  EXPECT_EQ(textOf(wire->match).size(), sizeof(pool_MatchId) - 1);
  EXPECT_TRUE(terminated(wire->match));
}

}  // namespace
}  // namespace pool::net
