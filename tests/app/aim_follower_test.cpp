// The viewer's glide toward the other shooter's live aim (no overshoot, the short way round, hidden
// when stale, a stroke once) and the shooter's pacing of its aims (rate cap, keep-alive, stroke).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "client/app/aim_follower.h"
#include "client/net/aim_pacer.h"

namespace pool::app {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

protocol::AimSample aimAt(double yaw, std::uint32_t seq, std::uint32_t shot = 3, int seat = 1) {
  protocol::AimSample a;
  a.match = "srv-1";
  a.seat = seat;
  a.seq = seq;
  a.shot_number = shot;
  a.yaw = yaw;
  a.power = 0.2;
  a.cue_ball_x = -0.6;
  return a;
}

TEST(AimFollower, GlidesWithoutOvershootAndSettlesOnTheLatestAim) {
  AimFollower f;
  f.receive(aimAt(0.0, 1), 0.0);
  f.advance(0.0);
  ASSERT_TRUE(f.shown());
  EXPECT_DOUBLE_EQ(f.shown()->aim.yaw, 0.0);
  f.receive(aimAt(30 * kDeg, 2), 0.01);
  double last = 0.0;
  bool moved_between = false;
  for (int i = 1; i <= 30; ++i) {
    const double now = 0.01 + i / 60.0;
    if (i % 10 == 0) f.receive(aimAt(30 * kDeg, 2 + static_cast<std::uint32_t>(i)), now);
    f.advance(now);
    const double yaw = f.shown()->aim.yaw;
    EXPECT_GE(yaw, last - 1e-12) << "the glide never turns back";
    EXPECT_LE(yaw, 30 * kDeg + 1e-9) << "no overshoot";
    if (yaw > 1 * kDeg && yaw < 29 * kDeg) moved_between = true;
    last = yaw;
  }
  EXPECT_TRUE(moved_between) << "the cue glides through the angles between";
  EXPECT_NEAR(f.shown()->aim.yaw, 30 * kDeg, 0.1 * kDeg) << "settled after half a second";
  EXPECT_NEAR(f.shown()->cue_ball.x(), -0.6, 1e-9);
}

TEST(AimFollower, TurnsTheShortWayRoundThePi) {
  AimFollower f;
  f.receive(aimAt(179 * kDeg, 1), 0.0);
  f.advance(0.0);
  f.receive(aimAt(-179 * kDeg, 2), 0.0);
  for (int i = 1; i <= 60; ++i) {
    f.advance(i / 60.0);
    const double yaw = f.shown()->aim.yaw;
    EXPECT_GT(std::abs(yaw), 178.9 * kDeg) << "through 180 degrees, never back through 0";
  }
  EXPECT_NEAR(angleBetween(f.shown()->aim.yaw, -179 * kDeg), 0.0, 0.01 * kDeg);
}

TEST(AimFollower, HiddenWhenStaleAfterAStrokeAndWhenForgotten) {
  AimFollower f(25.0, 1.0);
  EXPECT_FALSE(f.shown());
  f.receive(aimAt(0.5, 1), 0.0);
  f.advance(0.9);
  EXPECT_TRUE(f.shown());
  f.advance(1.1);
  EXPECT_FALSE(f.shown()) << "no aim for over a second";
  f.receive(aimAt(0.6, 2), 1.2);
  f.advance(1.2);
  ASSERT_TRUE(f.shown());
  EXPECT_DOUBLE_EQ(f.shown()->aim.yaw, 0.6) << "after a gap it starts from the aim, no glide";
  protocol::AimSample stroke = aimAt(0.6, 3);
  stroke.stroke = true;
  stroke.power = 0.8;
  f.receive(stroke, 1.3);
  f.advance(1.3);
  EXPECT_FALSE(f.shown()) << "the stroke takes over";
  const auto taken = f.takeStroke();
  ASSERT_TRUE(taken);
  EXPECT_DOUBLE_EQ(taken->aim.power, 0.8);
  EXPECT_FALSE(f.takeStroke()) << "handed out once";
  f.receive(aimAt(0.1, 1, 4), 2.0);  // the next turn
  f.advance(2.0);
  EXPECT_TRUE(f.shown());
  f.forget();
  EXPECT_FALSE(f.shown());
}

TEST(AimPacer, CapsTheRateWhileTheCueMovesAndKeepsAliveWhileItRests) {
  client::AimPacer pacer({30.0, 0.25});
  int sent = 0;
  // The cue turns every 1/144 s for one second: at most 30 (+1 first) go out, at least 20.
  for (int i = 0; i < 144; ++i) sent += pacer.due(aimAt(0.001 * i, 0), i / 144.0) ? 1 : 0;
  EXPECT_LE(sent, 31);
  EXPECT_GE(sent, 20);
  // Resting for a second: a keep-alive about every 0.25 s.
  int alive = 0;
  for (int i = 0; i < 144; ++i) alive += pacer.due(aimAt(0.2, 0), 1.0 + i / 144.0) ? 1 : 0;
  EXPECT_GE(alive, 3);
  EXPECT_LE(alive, 5);
  // A stroke goes out at once, and so does the first aim of a new turn.
  protocol::AimSample stroke = aimAt(0.2, 0);
  stroke.stroke = true;
  EXPECT_TRUE(pacer.due(stroke, 2.0001));
  EXPECT_TRUE(pacer.due(aimAt(0.2, 0, 4), 2.0002));
}

}  // namespace
}  // namespace pool::app
