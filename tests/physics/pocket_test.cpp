// Pockets are geometry: a ball sent straight in drops; a slow ball at a steep angle rattles on a
// jaw and stays out.
#include <gtest/gtest.h>

#include "fixtures.h"

namespace pool::physics::test {
namespace {

TEST(Pocket, StraightInDropsAndEndsPocketed) {
  const auto& t = realTable();
  const double R = t.spec.params.ball_radius;
  const Vec2 corner(t.spec.length / 2, t.spec.width / 2);
  const Vec2 start = corner - 0.5 * Vec2(1, 1).normalized();
  CueShot shot;
  shot.yaw = 45 * kDeg;
  shot.speed = 1.0;
  shot.speed_is_ball = true;
  const auto out = shootReal({ballAt(0, start.x(), start.y(), R)}, shot);
  const auto pockets = eventsOf(out, EventType::Pocket, 0);
  ASSERT_EQ(pockets.size(), 1u);
  EXPECT_EQ(pockets[0].where, "foot_left_corner");
  EXPECT_EQ(ballById(out, 0).state, MotionState::Pocketed);
  EXPECT_EQ(ballById(out, 0).pocket, "foot_left_corner");
  EXPECT_TRUE(eventsOf(out, EventType::BallCushion, 0).empty());
  // It fell through the hole (ODE, on the collision mesh) and lies in the trough beneath it.
  const Ball& cue = ballById(out, 0);
  EXPECT_LT(cue.pos.z(), -t.spec.slate_thickness);
  for (const auto& h : t.geometry.holes) {
    if (h.name == "foot_left_corner") {
      EXPECT_LT((cue.pos.head<2>() - h.centre).norm(), h.radius);
    }
  }
}

TEST(Pocket, SideStraightInDrops) {
  const auto& t = realTable();
  const double R = t.spec.params.ball_radius;
  CueShot shot;
  shot.yaw = 90 * kDeg;
  shot.speed = 0.8;
  shot.speed_is_ball = true;
  const auto out = shootReal({ballAt(0, 0.0, 0.0, R)}, shot);
  const auto pockets = eventsOf(out, EventType::Pocket, 0);
  ASSERT_EQ(pockets.size(), 1u);
  EXPECT_EQ(pockets[0].where, "left_side");
}

// A slow ball (0.6 m/s, rolling) coming in 25° off the corner pocket's axis, aimed 4 cm off the
// mouth's centre toward the foot-rail jaw, rattles between the jaws and stays on the table.
TEST(Pocket, SlowBallAtSteepAngleRattlesOnTheJawAndStaysOut) {
  const auto& t = realTable();
  const double R = t.spec.params.ball_radius;
  const Vec2 corner(t.spec.length / 2, t.spec.width / 2);
  const Vec2 mouth_centre = corner - t.spec.corner.mouth / 2 / std::sqrt(2.0) * Vec2(1, 1);
  const Vec2 target = mouth_centre - 0.04 * Vec2(1, -1).normalized();
  const double heading = 70 * kDeg;
  const Vec2 start = target - 0.5 * Vec2(std::cos(heading), std::sin(heading));
  CueShot shot;
  shot.yaw = heading;
  shot.speed = 0.6;
  shot.speed_is_ball = true;
  shot.tip_height = 0.4;  // rolling
  const auto out = shootReal({ballAt(0, start.x(), start.y(), R)}, shot);
  int jaw_hits = 0;
  for (const auto& e : eventsOf(out, EventType::BallCushion, 0)) {
    jaw_hits += e.where == "jaw_foot_left_corner";
  }
  EXPECT_GE(jaw_hits, 2) << "no rattle";
  EXPECT_TRUE(eventsOf(out, EventType::Pocket, 0).empty()) << "it dropped";
  EXPECT_EQ(ballById(out, 0).state, MotionState::Stationary);

  // The same ball sent down the pocket's axis drops.
  shot.yaw = 45 * kDeg;
  const Vec2 straight = mouth_centre - 0.5 * Vec2(1, 1).normalized();
  const auto in = shootReal({ballAt(0, straight.x(), straight.y(), R)}, shot);
  EXPECT_EQ(eventsOf(in, EventType::Pocket, 0).size(), 1u);
}

}  // namespace
}  // namespace pool::physics::test
