// Each turn opens behind the cue ball facing the nearest ball the shooter may hit, with the last
// turn's orbit, height, tip and elevation gone.
#include "client/app/turn_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app_fixture.h"
#include "rules/ball_groups.h"

namespace pool::app::test {
namespace {

physics::Ball ballAt(int id, double x, double y) {
  physics::Ball b;
  b.id = id;
  b.pos = Eigen::Vector3d(x, y, kRadius);
  return b;
}

TEST(TurnViewTest, TheTurnFacesTheNearestBallOfTheShootersGroup) {
  rules::GameState state;
  state.phase = rules::Phase::Assigned;
  state.shooter = 1;
  state.groups = {rules::Group::Solids, rules::Group::Stripes};
  const Eigen::Vector2d cue(0.0, 0.0);
  const std::vector<physics::Ball> balls{ballAt(0, 0.0, 0.0), ballAt(2, 0.1, 0.0),
                                         ballAt(8, 0.0, 0.15), ballAt(12, -0.3, -0.3),
                                         ballAt(11, 0.5, 0.5)};
  const auto yaw = turnStartYaw(cue, balls, state, rules::Game::EightBall);
  ASSERT_TRUE(yaw);
  EXPECT_NEAR(*yaw, std::atan2(-0.3, -0.3), 1e-12);  // the 12, not the nearer 2 or 8
  state.shooter = 0;
  EXPECT_NEAR(*turnStartYaw(cue, balls, state, rules::Game::EightBall), 0.0,
              1e-12);  // the 2 for solids
}

TEST(TurnViewTest, OnTheEightTheTurnFacesTheEight) {
  rules::GameState state;
  state.phase = rules::Phase::Assigned;
  state.groups = {rules::Group::Solids, rules::Group::Stripes};
  std::vector<physics::Ball> balls{ballAt(0, 0.0, 0.0), ballAt(8, 0.0, -0.6), ballAt(12, 0.1, 0.0)};
  EXPECT_NEAR(*turnStartYaw({0.0, 0.0}, balls, state, rules::Game::EightBall), -std::acos(0.0),
              1e-12);
}

// 9- and 10-ball: the lowest numbered ball on the table is the one to hit first (the WPA's rules
// of both games), however near the others lie.
TEST(TurnViewTest, InRotationGamesTheTurnFacesTheLowestBall) {
  rules::GameState state;
  state.phase = rules::Phase::Open;
  const std::vector<physics::Ball> balls{ballAt(0, 0.0, 0.0), ballAt(7, 0.1, 0.0),
                                         ballAt(4, -0.5, 0.2), ballAt(9, 0.0, 0.12)};
  for (rules::Game game : {rules::Game::NineBall, rules::Game::TenBall}) {
    const auto yaw = turnStartYaw({0.0, 0.0}, balls, state, game);
    ASSERT_TRUE(yaw);
    EXPECT_NEAR(*yaw, std::atan2(0.2, -0.5), 1e-12);  // the 4, not the nearer 7 or 9
  }
  // The same table in 8-ball with open groups: the nearest ball but the 8, the 7.
  EXPECT_NEAR(*turnStartYaw({0.0, 0.0}, balls, state, rules::Game::EightBall), 0.0, 1e-12);
}

TEST(TurnViewTest, TheBreakFacesTheRackAndAnEmptyTableNothing) {
  const rules::GameState state = rules::newRack(0);
  std::vector<physics::Ball> balls{ballAt(0, -0.7, 0.1), ballAt(1, 0.635, 0.0),
                                   ballAt(9, 0.68, 0.03)};
  EXPECT_NEAR(*turnStartYaw({-0.7, 0.1}, balls, state, rules::Game::EightBall),
              std::atan2(-0.1, 1.335), 1e-12);
  balls.resize(1);
  EXPECT_FALSE(turnStartYaw({-0.7, 0.1}, balls, state, rules::Game::EightBall));
}

TEST(TurnViewTest, ANewTurnDropsTheLastTurnsOrbitHeightTipAndElevation) {
  Controls controls = nineFootControls();
  const Eigen::Vector3d cue(-0.8, 0.1, kRadius);
  controls.startTurn(cue, rules::BallInHand::None);
  const Orbit fresh = controls.camera().aimingOrbit();
  hold(controls, Key::Left, 0.6, {.shift = true});
  hold(controls, Key::Up, 0.5);
  hold(controls, Key::S, 0.5);
  hold(controls, Key::A, 0.6);
  hold(controls, Key::Up, 0.3, {.ctrl = true});
  ASSERT_GT(std::abs(controls.camera().aimingOrbit().azimuth - fresh.azimuth), 0.3);
  ASSERT_TRUE(controls.takeShot() == std::nullopt);
  ASSERT_TRUE(shoot(controls, 0.2));

  controls.startTurn(cue, rules::BallInHand::None);
  controls.setYaw(1.2);
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  const Orbit next = controls.camera().aimingOrbit();
  EXPECT_NEAR(std::remainder(next.azimuth - (1.2 + std::acos(-1.0)), 2 * std::acos(-1.0)), 0.0,
              1e-12);
  EXPECT_DOUBLE_EQ(next.elevation, fresh.elevation);
  EXPECT_DOUBLE_EQ(next.distance, fresh.distance);
  EXPECT_EQ(controls.aim().elevation, 0.0);
  EXPECT_EQ(controls.aim().tip_height, 0.0);
  EXPECT_EQ(controls.aim().tip_side, 0.0);
  const ViewPoint view = controls.camera().view();
  const Eigen::Vector2d back = (view.eye - view.target).head<2>().normalized();
  EXPECT_NEAR(back.dot(Eigen::Vector2d(std::cos(1.2), std::sin(1.2))), -1.0, 1e-9);
}

}  // namespace
}  // namespace pool::app::test
