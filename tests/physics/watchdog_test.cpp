// The watchdog: impossible ball states are re-spotted or removed with a reason, never a crash.
#include <gtest/gtest.h>

#include "fixtures.h"
#include "physics/watchdog.h"

namespace pool::physics::test {
namespace {

const TableFeatures& features() {
  static const TableFeatures f = TableFeatures::from(realTable().geometry);
  return f;
}

TEST(Watchdog, HealthyTableNeedsNothing) {
  EXPECT_TRUE(checkBalls(breakBalls(), features(), realTable().spec.params).empty());
}

TEST(Watchdog, NonFiniteBallIsRespottedOnTheLongString) {
  auto balls = breakBalls();
  balls[0].vel.x() = std::nan("");
  const auto fixes = checkBalls(balls, features(), realTable().spec.params);
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_EQ(fixes[0].index, 0u);
  EXPECT_EQ(fixes[0].reason, "non-finite state");
  EXPECT_FALSE(fixes[0].remove);
  EXPECT_DOUBLE_EQ(fixes[0].spot.y(), 0.0);  // on the long string
  // The spot is free: the rack sits on the foot spot, so it is behind or in front of it.
  for (size_t i = 1; i < balls.size(); ++i) {
    EXPECT_GE((balls[i].pos.head<2>() - fixes[0].spot).norm(), 2 * balls[i].pos.z() - 1e-12);
  }
}

TEST(Watchdog, BallInsideAnotherIsRespotted) {
  auto balls = breakBalls();
  balls[0].pos = balls[1].pos + Vec3(0.01, 0, 0);
  const auto fixes = checkBalls(balls, features(), realTable().spec.params);
  ASSERT_FALSE(fixes.empty());
  EXPECT_EQ(fixes[0].reason, "inside another ball");
}

TEST(Watchdog, BallOffEverySurfaceIsRespotted) {
  auto balls = breakBalls();
  balls[3].pos = Vec3(5.0, 0.0, 0.028575);
  const auto fixes = checkBalls(balls, features(), realTable().spec.params);
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_EQ(fixes[0].reason, "left the slate");
}

TEST(Watchdog, AnOrdinaryShotNeverNeedsIt) {
  const auto& t = realTable();
  Simulation sim(t.spec, t.geometry);
  std::vector<Ball> balls{ballAt(0, 0.0, 0.0), ballAt(1, 0.3, 0.0)};
  balls[0].vel = Vec3(1, 0, 0);
  balls[0].state = MotionState::Sliding;
  ASSERT_TRUE(sim.setBalls(balls));
  const auto out = sim.run();
  for (const auto& e : out.events) EXPECT_NE(e.type, EventType::Respot);
  EXPECT_TRUE(out.t_rest.has_value());
}

}  // namespace
}  // namespace pool::physics::test

namespace pool::physics::test {
namespace {

// A ball that stopped in the left side pocket's mouth (past the rails' nose line, short of the
// hole) is on the slate; the next shot must accept that layout.
TEST(Placement, BallRestingInAPocketMouthIsOnTheSlate) {
  const auto& t = realTable();
  const auto& p = t.spec.params;
  EXPECT_TRUE(onSlate(Vec2(0.035, 0.638), features(), p));
  EXPECT_TRUE(checkPlacement({ballAt(0, 0.0, 0.0), ballAt(2, 0.035, 0.638)}, t.geometry, p).ok());
  // Inside the rail beside the mouth, over the hole, or beyond the table: not on the slate.
  EXPECT_FALSE(onSlate(Vec2(0.3, 0.62), features(), p));
  EXPECT_FALSE(onSlate(Vec2(0.0, 0.70), features(), p));
  EXPECT_FALSE(onSlate(Vec2(2.0, 0.0), features(), p));
}

}  // namespace
}  // namespace pool::physics::test
