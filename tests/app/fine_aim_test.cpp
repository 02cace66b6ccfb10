// Aim a player can trust: every press of an arrow turns the cue one step (0.05° with Alt), a
// held arrow turns it by the time held however that time falls into frames, and the mouse aims
// finer than a pixel with Alt.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app_fixture.h"

namespace pool::app::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

class FineAimTest : public ::testing::Test {
 protected:
  void SetUp() override {
    controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  }
  Controls controls = nineFootControls();
};

TEST_F(FineAimTest, APressWithAltTurnsTheCueAtMostAHundredthOfADegreeTimesFive) {
  for (int press = 1; press <= 10; ++press) {
    controls.keyDown(Key::Left, {.alt = true});
    controls.advance(1.0 / 60);
    controls.keyUp(Key::Left);
    controls.advance(1.0 / 60);
    EXPECT_NEAR(controls.aim().yaw, press * ControlRates{}.fine_yaw_step, 1e-12);
  }
  EXPECT_LE(ControlRates{}.fine_yaw_step, 0.05 * kDeg + 1e-12);
  controls.keyDown(Key::Right, {.alt = true});
  controls.keyUp(Key::Right);
  EXPECT_NEAR(controls.aim().yaw, 9 * ControlRates{}.fine_yaw_step, 1e-12);
}

TEST_F(FineAimTest, ATapBetweenTwoFramesStillTurnsTheCue) {
  // A 12 ms tap falls between two 16.7 ms frames: no advance sees the key held.
  controls.keyDown(Key::Right, {});
  controls.keyUp(Key::Right);
  controls.advance(1.0 / 60);
  EXPECT_NEAR(controls.aim().yaw, -ControlRates{}.yaw_step, 1e-12);
}

TEST_F(FineAimTest, TheTurnOfAHeldArrowDependsOnTheTimeHeldNotOnTheFrames) {
  // The same 0.7 s hold (coarse and fine) at 144 Hz, 60 Hz, 7 Hz and in uneven frames.
  for (const bool fine : {false, true}) {
    std::vector<double> yaws;
    for (const std::vector<double>& frames :
         {std::vector<double>(101, 0.7 / 101), std::vector<double>(42, 0.7 / 42),
          std::vector<double>(5, 0.14), std::vector<double>{0.013, 0.3, 0.001, 0.2, 0.186}}) {
      Controls c = nineFootControls();
      c.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
      c.keyDown(Key::Left, {.alt = fine});
      for (const double dt : frames) c.advance(dt);
      c.keyUp(Key::Left);
      yaws.push_back(c.aim().yaw);
    }
    for (const double yaw : yaws) EXPECT_NEAR(yaw, heldTurn(0.7, fine), 1e-12) << fine;
  }
}

TEST_F(FineAimTest, TheMouseWithAltAimsFinerThanAPixel) {
  const double per_px = ControlRates{}.fine_mouse_yaw;
  controls.mouseButton(MouseButton::Left, true, 600.0, 400.0, {.alt = true});
  controls.mouseMove(601.0, 400.0);  // within a click's slop: nothing yet
  EXPECT_EQ(controls.aim().yaw, 0.0);
  controls.mouseMove(605.25, 400.0);  // a drag: all of it counts
  EXPECT_NEAR(controls.aim().yaw, -5.25 * per_px, 1e-15);
  controls.mouseMove(605.5, 400.0);  // then a quarter of a pixel more
  EXPECT_NEAR(controls.aim().yaw, -5.5 * per_px, 1e-15);
  controls.mouseMove(705.5, 400.0);
  controls.mouseButton(MouseButton::Left, false, 705.5, 400.0);
  EXPECT_NEAR(controls.aim().yaw, -105.5 * per_px, 1e-15);
  EXPECT_LT(100.0 * per_px, 1.2 * kDeg);  // a hundred pixels for about a degree
}

TEST_F(FineAimTest, ClickingABallThenAPocketCallsIt) {
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  ClickTargets targets;
  targets.balls = {{5, Eigen::Vector2d(0.2, 0.3)}, {11, Eigen::Vector2d(0.5, -0.2)}};
  targets.pockets = {{"foot_left_corner", Eigen::Vector2d(1.27, 0.635)},
                     {"side_left", Eigen::Vector2d(0.0, 0.66)}};
  controls.setClickTargets(targets);
  controls.suggestCall({.ball = 11, .pocket = "side_left"});
  auto pixel = [&](const Eigen::Vector2d& at) {
    const glm::vec3 p = render::projectToPixels(
        cameraOf(controls.camera().view()), 1280, 720,
        glm::vec3(static_cast<float>(at.x()), static_cast<float>(at.y()), kRadius));
    return Eigen::Vector2d(p.x, p.y);
  };
  auto clickAt = [&](const Eigen::Vector2d& at) {
    const Eigen::Vector2d px = pixel(at);
    controls.mouseButton(MouseButton::Left, true, px.x(), px.y());
    controls.mouseMove(px.x() + 1.0, px.y());  // a hand's tremble
    controls.mouseButton(MouseButton::Left, false, px.x() + 1.0, px.y());
  };
  const double yaw = controls.aim().yaw;
  clickAt({0.2, 0.3});
  EXPECT_EQ(controls.pickedBall(), 5);
  clickAt({1.2, 0.6});  // near the corner's mouth
  EXPECT_FALSE(controls.pickedBall());
  EXPECT_EQ(controls.aim().call.ball, 5);
  EXPECT_EQ(controls.aim().call.pocket, "foot_left_corner");
  EXPECT_TRUE(controls.aim().call.by_player);
  EXPECT_EQ(controls.aim().yaw, yaw);  // clicks do not turn the cue
  controls.suggestCall({.ball = 11, .pocket = "side_left"});
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_EQ(shot->called_ball, 5);
  EXPECT_EQ(shot->called_pocket, "foot_left_corner");
  EXPECT_TRUE(wireCheck(*shot).ok());
}

}  // namespace
}  // namespace pool::app::test
