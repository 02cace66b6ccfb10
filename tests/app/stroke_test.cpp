// Power a player controls: a mouse stroke (Ctrl + drag) strikes at the cue's speed at contact, and
// the - / + keys set the cue speed in exact steps that Enter shoots.
#include <gtest/gtest.h>

#include <cmath>

#include "app_fixture.h"

namespace pool::app::test {
namespace {

const ControlRates kStrokeRates{};
const protocol::CommandLimits kServerLimits{};
constexpr double kFrame = 1.0 / 60.0;

class StrokeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  }

  /// One frame of the window: the mouse moved by (dx, dy) pixels, then the frame's advance.
  void frame(double dx, double dy) {
    at += Eigen::Vector2d(dx, dy);
    controls.mouseMove(at.x(), at.y());
    controls.advance(kFrame);
  }

  /// Ctrl + press at the window's centre, `back` frames of `down` pixels down.
  void drawBack(int frames, double down) {
    controls.mouseButton(MouseButton::Left, true, at.x(), at.y(), {.ctrl = true});
    for (int i = 0; i < frames; ++i) frame(0.0, down);
  }

  Controls controls = nineFootControls();
  Eigen::Vector2d at{640.0, 360.0};
};

TEST_F(StrokeTest, TheShotGoesAtTheCuesSpeedWhenItsTipReachesTheBall) {
  // Drawn back 15 frames of 10 px (0.15 m at 1 mm a pixel), then pushed up 60 px a frame: the tip
  // is at 0.09, 0.03, then 0.03 m past the ball, so the third frame strikes, at 60 px × 1 mm a
  // pixel in 1/60 s = 3.6 m/s (the stroke's travel over the frame the tip reached the ball).
  drawBack(15, 10.0);
  ASSERT_TRUE(controls.aim().stroke_back);
  EXPECT_NEAR(*controls.aim().stroke_back, 15 * 10.0 * kStrokeRates.stroke_scale, 1e-12);
  frame(0.0, -60.0);
  frame(0.0, -60.0);
  EXPECT_FALSE(controls.takeShot()) << "the tip is still 3 cm short of the ball";
  frame(0.0, -60.0);
  const auto shot = controls.takeShot();
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->cue.speed, 60.0 * kStrokeRates.stroke_scale / kFrame, 1e-9);
  EXPECT_EQ(controls.mode(), ControlMode::Watching);
  EXPECT_EQ(controls.strokeNote(), "stroke 3.60 m/s");
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(StrokeTest, SidewaysMovementDuringTheStrokeDoesNotTurnTheCue) {
  const double yaw = controls.aim().yaw;
  drawBack(10, 10.0);
  frame(80.0, 0.0);
  frame(-30.0, -50.0);
  frame(25.0, -50.0);
  EXPECT_DOUBLE_EQ(controls.aim().yaw, yaw);
  const auto shot = controls.takeShot();
  ASSERT_TRUE(shot);
  EXPECT_DOUBLE_EQ(shot->cue.yaw, yaw);
  EXPECT_NEAR(shot->cue.speed, 50.0 * kStrokeRates.stroke_scale / kFrame, 1e-9);
}

TEST_F(StrokeTest, LettingGoBeforeContactOrEscCancelsIt) {
  drawBack(10, 10.0);
  frame(0.0, -40.0);
  controls.mouseButton(MouseButton::Left, false, at.x(), at.y());
  for (int i = 0; i < 5; ++i) frame(0.0, -40.0);
  EXPECT_FALSE(controls.takeShot());
  EXPECT_FALSE(controls.aim().stroke_back);
  EXPECT_EQ(controls.mode(), ControlMode::Aiming);
  EXPECT_NE(controls.strokeNote().find("no shot"), std::string::npos) << controls.strokeNote();

  drawBack(10, 10.0);
  controls.keyDown(Key::Escape, {});
  for (int i = 0; i < 5; ++i) frame(0.0, -40.0);
  EXPECT_FALSE(controls.takeShot());
  EXPECT_FALSE(controls.stroking());
  EXPECT_NE(controls.strokeNote().find("cancelled"), std::string::npos) << controls.strokeNote();
}

TEST_F(StrokeTest, AStrokePastTheLimitIsPlayedAtTheLimitAndSaidSo) {
  // 250 px in a frame: 15 m/s, past the server's 12 m/s.
  drawBack(20, 10.0);
  frame(0.0, -250.0);
  const auto shot = controls.takeShot();
  ASSERT_TRUE(shot);
  EXPECT_DOUBLE_EQ(shot->cue.speed, kServerLimits.max_speed);
  EXPECT_EQ(controls.strokeNote(), "stroke 15.00 m/s: over the limit, played at 12.00 m/s");
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(StrokeTest, APushWithoutADrawBackIsNoStroke) {
  // Less than kMinStrokeBack (1 cm) drawn: the tip rests at the ball, whatever the push.
  drawBack(1, 5.0);
  frame(0.0, -100.0);
  frame(0.0, -100.0);
  EXPECT_FALSE(controls.takeShot());
  ASSERT_TRUE(controls.aim().stroke_back);
  EXPECT_DOUBLE_EQ(*controls.aim().stroke_back, 0.0);
}

TEST_F(StrokeTest, PowerKeysStepTheCueSpeedExactlyAndEnterShoots) {
  // From the slowest, 0.30 m/s: 13 presses of + make 0.95; Shift + - goes to the next multiple of
  // 0.5 down, 0.50; four presses of - make 0.30, and a fifth stays at the slowest.
  for (int i = 0; i < 13; ++i) controls.keyDown(Key::Equal, {});
  EXPECT_NEAR(cueSpeedOf(controls.aim().power, kServerLimits), 0.95, 1e-12);
  controls.keyDown(Key::Minus, {.shift = true});
  EXPECT_NEAR(cueSpeedOf(controls.aim().power, kServerLimits), 0.50, 1e-12);
  for (int i = 0; i < 5; ++i) controls.keyDown(Key::Minus, {});
  EXPECT_NEAR(cueSpeedOf(controls.aim().power, kServerLimits), kMinCueSpeed, 1e-12);
  controls.keyDown(Key::Enter, {});
  const auto touch = controls.takeShot();
  ASSERT_TRUE(touch);
  EXPECT_NEAR(touch->cue.speed, 0.30, 1e-12);

  // While the bar charges the keys do nothing; the release shoots the charge.
  controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  controls.keyDown(Key::Space, {});
  for (int i = 0; i < 7; ++i) controls.advance(kFrame);
  const double charged = cueSpeedOf(controls.aim().power, kServerLimits);
  controls.keyDown(Key::Equal, {});
  EXPECT_DOUBLE_EQ(cueSpeedOf(controls.aim().power, kServerLimits), charged);
  controls.keyUp(Key::Space);
  const auto charge = controls.takeShot();
  ASSERT_TRUE(charge);
  EXPECT_DOUBLE_EQ(charge->cue.speed, charged);

  // Shift + + up to the limit, which it does not pass; - then steps 0.05 below it.
  controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  for (int i = 0; i < 30; ++i) controls.keyDown(Key::Equal, {.shift = true});
  EXPECT_DOUBLE_EQ(cueSpeedOf(controls.aim().power, kServerLimits), kServerLimits.max_speed);
  controls.keyDown(Key::Minus, {});
  EXPECT_NEAR(cueSpeedOf(controls.aim().power, kServerLimits), kServerLimits.max_speed - 0.05,
              1e-12);
}

}  // namespace
}  // namespace pool::app::test
