// Jump shots clear a blocker after a slate bounce; massé shots curve.
#include <gtest/gtest.h>

#include "fixtures.h"

namespace pool::physics::test {
namespace {

constexpr double R = 0.028575;

/// True if ball `id` is hit before time t.
bool ballHit(const ShotOutcome& o, int id, double before = 1e9) {
  for (const auto& e : o.events) {
    if (e.t >= before) break;
    if (e.type == EventType::BallBall && (e.ball_a == id || e.ball_b == id)) return true;
  }
  return false;
}

// Elevated 45°, the cue's line through the centre: the ball is driven into the slate, bounces
// (e_slate = 0.5) and flies over a ball 0.15 m (2.6 ball widths) ahead; a level cue hits it.
TEST(Jump, ElevatedCueBouncesOffTheSlateAndClearsABlocker) {
  const std::vector<Ball> balls{ballAt(0, -0.8, 0.0), ballAt(5, -0.8 + 0.15, 0.0)};
  CueShot shot;
  shot.speed = 4.0;
  shot.elevation = 45 * kDeg;
  const auto out = shootReal(balls, shot);
  ASSERT_FALSE(out.events.empty());
  EXPECT_FALSE(eventsOf(out, EventType::Airborne, 0).empty());
  const auto lands = eventsOf(out, EventType::Land, 0);
  ASSERT_FALSE(lands.empty());
  EXPECT_GT(lands.front().pos.x(), -0.8 + 0.15 + 2 * R) << "landed short of the blocker";
  EXPECT_FALSE(ballHit(out, 5, lands.front().t)) << "the jump did not clear the blocker";

  shot.elevation = 0.0;
  EXPECT_TRUE(ballHit(shootReal(balls, shot), 5)) << "a level cue must hit the blocker";
}

// Massé: cue at 70° with right English. The spin's horizontal axis is tilted from the roll axis,
// so friction curves the path to the right; the heading turns by tens of degrees. The ball leaves
// along the cue's line (the first slate impact happens under the tip: no friction) and curves as
// the cloth grips it, in its landings and while it slides.
TEST(Masse, HighElevationWithSideCurves) {
  CueShot shot;
  shot.speed = 3.0;
  shot.elevation = 70 * kDeg;
  shot.tip_side = 0.4;
  SimOptions opt;
  opt.sample_hz = 200;
  const auto out = shootReal({ballAt(0, -0.9, 0.3)}, shot, opt);
  ASSERT_GT(out.trajectory.size(), 10u);
  double min_heading = 0, max_heading = 0;
  bool first = true;
  for (const auto& s : out.trajectory) {
    const Vec3 v = s.balls[0].vel;
    if (v.head<2>().norm() < 0.05 || s.balls[0].state == MotionState::Stationary) continue;
    if (!eventsOf(out, EventType::BallCushion, 0).empty() &&
        s.t >= eventsOf(out, EventType::BallCushion, 0).front().t) {
      break;  // the curve before any cushion
    }
    const double h = std::atan2(v.y(), v.x()) / kDeg;
    if (first) min_heading = max_heading = h;
    first = false;
    min_heading = std::min(min_heading, h);
    max_heading = std::max(max_heading, h);
  }
  EXPECT_GT(max_heading - min_heading, 20.0) << "the path did not curve";
  // Curving right of a +x heading means the heading falls (clockwise seen from above).
  const Vec3 v0 = out.trajectory[1].balls[0].vel;
  EXPECT_LT(min_heading, std::atan2(v0.y(), v0.x()) / kDeg);
}

}  // namespace
}  // namespace pool::physics::test
