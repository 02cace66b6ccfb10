// Closed-form checks of the cloth model on an open slate (docs/PHYSICS.md: Leckie & Greenspan,
// Alciatore).
#include <gtest/gtest.h>

#include "fixtures.h"

namespace pool::physics::test {
namespace {

constexpr double g = kGravity;

// A centre hit at 2 m/s cue speed gives v0 = 3.07694 m/s (docs/PHYSICS.md); all else follows
// from u_s = 0.2 and u_r = 0.01. The event times come from the engine's analytic transition
// times and the distances from ODE's integration, so they must agree to far better than the
// 1 % the issue allows: 1e-6 relative.
TEST(Cloth, StunShotSlidesThenRollsAtFiveSeventhsThenStops) {
  const auto spec = openSpec();
  CueShot shot;
  shot.speed = 2.0;
  const auto out = shootOpen(spec, {ballAt(0, -30.0, 0.0)}, shot);
  ASSERT_FALSE(out.events.empty());
  const double v0 = 2.0 * 2.0 / (1.0 + spec.params.ball_mass / spec.params.cue_mass);
  EXPECT_NEAR(v0, 3.07694, 1e-5);

  const auto roll = eventsOf(out, EventType::SlideToRoll, 0);
  ASSERT_EQ(roll.size(), 1u);
  const double ts = 2.0 * v0 / (7.0 * 0.2 * g);
  const double ds = 12.0 * v0 * v0 / (49.0 * 0.2 * g);
  EXPECT_NEAR(roll[0].t, 0.448076, 1e-6);
  EXPECT_NEAR(roll[0].t, ts, 1e-9 * ts);
  EXPECT_NEAR(roll[0].pos.x() + 30.0, 1.18174, 1e-5);
  EXPECT_NEAR(roll[0].pos.x() + 30.0, ds, 1e-6 * ds);

  const auto rest = eventsOf(out, EventType::RollToRest, 0);
  ASSERT_EQ(rest.size(), 1u);
  const double vr = 5.0 / 7.0 * v0;
  const double tr = vr / (0.01 * g);
  const double dr = vr * vr / (2.0 * 0.01 * g);
  EXPECT_NEAR(rest[0].t - roll[0].t, tr, 1e-6 * tr);
  EXPECT_NEAR(rest[0].pos.x() - roll[0].pos.x(), dr, 1e-6 * dr);
  ASSERT_TRUE(out.t_rest.has_value());
  EXPECT_NEAR(*out.t_rest, ts + tr, 1e-6);
  EXPECT_EQ(ballById(out, 0).state, MotionState::Stationary);
}

TEST(Cloth, RollSpeedAfterSlidingIsFiveSeventhsOfStrikeSpeed) {
  const auto spec = openSpec();
  CueShot shot;
  shot.speed = 2.0;
  SimOptions opt;
  opt.sample_hz = 1000.0;
  const auto out = shootOpen(spec, {ballAt(0, -30.0, 0.0)}, shot, opt);
  const auto roll = eventsOf(out, EventType::SlideToRoll, 0);
  ASSERT_EQ(roll.size(), 1u);
  // Sample just after the transition: v = 2.19781 − u_r g (t − t_s) and ω R = v.
  const Sample* s = sampleAfter(out, roll[0].t);
  ASSERT_NE(s, nullptr) << "no sample after the ball began to roll";
  const Ball& b = s->balls[0];
  const double expected = 2.19781 - 0.01 * g * (s->t - roll[0].t);
  EXPECT_NEAR(b.vel.x(), expected, 1e-5);
  EXPECT_NEAR(b.ang_vel.y() * spec.params.ball_radius, b.vel.x(), 1e-9);
}

// Follow, draw (docs/PHYSICS.md): cue 2 m/s, b = ±0.5 → v0 = 2.07793, |ω| = 90.898 rad/s; follow
// rolls at 2.22635 m/s after 0.075649 s, draw at 0.74212 m/s after 0.680841 s. Tolerance 1e-5
// relative (the published figures have six significant digits).
TEST(Cloth, FollowAndDrawRollSpeedsAndTimes) {
  const auto spec = openSpec();
  struct Case {
    double b, speed, time;
  };
  for (const Case c : {Case{0.5, 2.22635, 0.075649}, Case{-0.5, 0.74212, 0.680841}}) {
    CueShot shot;
    shot.speed = 2.0;
    shot.tip_height = c.b;
    SimOptions opt;
    opt.sample_hz = 10000.0;
    const auto out = shootOpen(spec, {ballAt(0, -30.0, 0.0)}, shot, opt);
    ASSERT_GT(out.trajectory.size(), 2u);
    EXPECT_NEAR(out.trajectory[0].balls[0].vel.x(), 2.07793, 1e-5);
    EXPECT_NEAR(std::abs(out.trajectory[0].balls[0].ang_vel.y()), 90.898, 1e-3);
    const auto roll = eventsOf(out, EventType::SlideToRoll, 0);
    ASSERT_EQ(roll.size(), 1u) << "b = " << c.b;
    EXPECT_NEAR(roll[0].t, c.time, 1e-5 * c.time) << "b = " << c.b;
    // Speed at the transition: sample within 0.1 ms after it, corrected by the rolling decel.
    const Sample* s = sampleFrom(out, roll[0].t);
    ASSERT_NE(s, nullptr) << "no sample once the ball rolls, b = " << c.b;
    const double v = s->balls[0].vel.x() + 0.01 * g * (s->t - roll[0].t);
    EXPECT_NEAR(v, c.speed, 1e-5 * c.speed) << "b = " << c.b;
  }
}

}  // namespace
}  // namespace pool::physics::test
