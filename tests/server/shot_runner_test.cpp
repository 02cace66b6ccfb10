// Shots through the physics: balls already down are carried through untouched, frames on the grid.
#include <gtest/gtest.h>

#include "game/rack_layout.h"
#include "match_fixture.h"
#include "physics/simulation.h"
#include "server/match/shot_runner.h"

namespace pool::server {
namespace {

using namespace test;

TEST(ShotRunner, BallsAlreadyDownStayOutAndComeBackUnchanged) {
  auto balls = game::rackLayout(*nineFoot(), 3);
  balls[9].state = physics::MotionState::Pocketed;
  balls[9].pocket = "foot_left_corner";
  balls[9].pos = physics::Vec3(1.4, 0.7, -0.1);
  physics::CueShot cue;
  cue.speed = 2.0;
  cue.yaw = 3.0;  // away from the rack
  auto outcome = runner()->run(balls, cue, 30.0, 60.0);
  ASSERT_TRUE(outcome) << outcome.error();
  ASSERT_EQ(outcome->balls.size(), 16u);
  EXPECT_EQ(outcome->balls[9].pos, balls[9].pos);
  EXPECT_EQ(outcome->balls[9].state, physics::MotionState::Pocketed);
  ASSERT_GT(outcome->trajectory.size(), 2u);
  for (std::size_t k = 0; k < outcome->trajectory.size(); ++k) {
    const auto& frame = outcome->trajectory[k];
    EXPECT_EQ(frame.t, static_cast<double>(k) / 30.0);
    ASSERT_EQ(frame.balls.size(), 16u);
    EXPECT_EQ(frame.balls[9].pos, balls[9].pos);
  }
}

TEST(ShotRunner, ALayoutThePhysicsRefusesFails) {
  auto balls = game::rackLayout(*nineFoot(), 3);
  balls[0].pos = balls[1].pos;
  physics::CueShot cue;
  cue.speed = 2.0;
  const auto outcome = runner()->run(balls, cue, 30.0, 60.0);
  ASSERT_FALSE(outcome);
  EXPECT_NE(outcome.error().find("overlaps"), std::string::npos) << outcome.error();
}

}  // namespace
}  // namespace pool::server
