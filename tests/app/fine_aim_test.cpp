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
  controls.mouseButton(MouseButton::Left, true, 600.0, 400.0, {.alt = true});
  controls.mouseMove(600.25, 400.0);  // a quarter of a pixel
  EXPECT_NEAR(controls.aim().yaw, -0.25 * ControlRates{}.fine_mouse_yaw, 1e-15);
  controls.mouseMove(700.25, 400.0);
  controls.mouseButton(MouseButton::Left, false, 700.25, 400.0);
  const double fine_100px = 100.0 * ControlRates{}.fine_mouse_yaw;
  EXPECT_NEAR(controls.aim().yaw, -100.25 * ControlRates{}.fine_mouse_yaw, 1e-15);
  EXPECT_LT(fine_100px, 1.2 * kDeg);  // a hundred pixels for about a degree
}

}  // namespace
}  // namespace pool::app::test
