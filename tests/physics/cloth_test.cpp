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

// The same closed forms on each table's own ball and cloth (docs/PHYSICS.md; Alciatore's strike
// and Leckie & Greenspan's cloth): a strike at cue speed c and tip offset b (fraction of R) gives
// v0 = 2c / (1 + m/M + 5b²/2) and ω0 = 5 v0 b / (2R); the ball slides until |v − ωR| is gone,
// taking 2|v0 − ω0R| / (7 u_s g), and rolls on at (5 v0 + 2 ω0 R) / 7. The snooker ball (52.5 mm,
// 142 g) and the carom ball (61.5 mm, 210 g) differ from the pool ball in size and mass, so in
// v0 and ω0; the cloth comes from each table's spec. Tolerance: 1e-6 relative for the analytic
// event time, 1e-5 for speeds read from samples. At b = 2/5 (2/5 of each ball's own radius) the
// ball rolls from the strike: no slide at all.
TEST(Cloth, EachTablesBallFollowsTheClosedFormsWithItsOwnSizeMassAndCloth) {
  for (const char* name : {"wpa-9ft", "snooker-12ft", "carom-match"}) {
    auto table = table::loadTableSpec(name);
    ASSERT_TRUE(table) << table.error();
    table::TableSpec spec = openSpec();
    spec.params = table->params;
    const double radius = spec.params.ball_radius, m = spec.params.ball_mass;
    const double M = spec.params.cue_mass, us = spec.params.u_s, ur = spec.params.u_r;
    for (const double b : {0.0, 0.4, 0.5, -0.3}) {
      CueShot shot;
      shot.speed = 2.0;
      shot.tip_height = b;
      SimOptions opt;
      opt.sample_hz = 1000.0;
      const auto out = shootOpen(spec, {ballAt(0, -30.0, 0.0, radius)}, shot, opt);
      ASSERT_GT(out.trajectory.size(), 2u) << name;
      const double v0 = 2.0 * 2.0 / (1.0 + m / M + 2.5 * b * b);
      const double w0 = 5.0 * v0 * b / (2.0 * radius);
      const Ball& first = out.trajectory[0].balls[0];
      EXPECT_NEAR(first.vel.x(), v0, 1e-6 * v0) << name << ", b = " << b;
      EXPECT_NEAR(first.ang_vel.y(), w0, 1e-6 * std::max(1.0, std::abs(w0)))
          << name << ", b = " << b;
      const auto roll = eventsOf(out, EventType::SlideToRoll, 0);
      if (b == 0.4) {
        EXPECT_NEAR(w0 * radius, v0, 1e-12) << name;  // natural roll
        EXPECT_TRUE(roll.empty() || roll[0].t < 1e-9) << name << ": slid for " << roll[0].t;
        continue;
      }
      ASSERT_EQ(roll.size(), 1u) << name << ", b = " << b;
      const double slide = 2.0 * std::abs(v0 - w0 * radius) / (7.0 * us * g);
      EXPECT_NEAR(roll[0].t, slide, 1e-6 * slide) << name << ", b = " << b;
      const Sample* s = sampleFrom(out, roll[0].t);
      ASSERT_NE(s, nullptr) << name;
      const double rolling = (5.0 * v0 + 2.0 * w0 * radius) / 7.0;
      const double v = s->balls[0].vel.x() + ur * g * (s->t - roll[0].t);
      EXPECT_NEAR(v, rolling, 1e-5 * rolling) << name << ", b = " << b;
    }
  }
}

}  // namespace
}  // namespace pool::physics::test
