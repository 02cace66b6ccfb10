// Changes of view glide instead of cutting, at the same pace whatever the frame rate; B goes back
// behind the cue, O looks straight down on the table.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app_fixture.h"
#include "client/app/camera_rig.h"

namespace pool::app::test {
namespace {

double gap(const ViewPoint& a, const ViewPoint& b) {
  return std::max((a.eye - b.eye).norm(), (a.target - b.target).norm());
}

/// A rig watching, then switched to aiming at a cue ball: the drawn view starts where it was.
CameraRig switchedToAiming() {
  CameraRig rig(2.54, 1.27, 1280.0 / 720.0);
  rig.followCue(Eigen::Vector3d(-0.6, 0.2, kRadius), 0.3);
  rig.setAiming(true);
  return rig;
}

TEST(CameraGlideTest, ASwitchOfCameraStartsFromTheViewDrawnAndEndsOnTheNewOne) {
  const CameraRig watching(2.54, 1.27, 1280.0 / 720.0);
  CameraRig rig = switchedToAiming();
  ASSERT_TRUE(rig.gliding());
  EXPECT_LT(gap(rig.view(), watching.view()), 1e-12);  // no cut
  const double total = gap(watching.view(), rig.goal());
  ASSERT_GT(total, 1.0);  // the overview and the aiming view are metres apart
  rig.update(kGlideTime / 2);
  const double left = gap(rig.view(), rig.goal());
  EXPECT_GT(left, 0.2 * total);
  EXPECT_LT(left, 0.8 * total);
  rig.update(kGlideTime / 2 + 1e-9);
  EXPECT_FALSE(rig.gliding());
  EXPECT_LT(gap(rig.view(), rig.goal()), 1e-12);
}

TEST(CameraGlideTest, NoFrameOfTheGlideJumps) {
  CameraRig rig = switchedToAiming();
  const double total = gap(rig.view(), rig.goal());
  ViewPoint last = rig.view();
  double largest = 0.0;
  for (int i = 0; i < 60; ++i) {
    rig.update(kGlideTime / 60);
    largest = std::max(largest, gap(rig.view(), last));
    last = rig.view();
  }
  // Eased: no 1/60 of the glide moves more than 1.5/60 of the way (a cut would move all of it).
  EXPECT_LT(largest, 1.5 * total / 60);
  EXPECT_FALSE(rig.gliding());
}

TEST(CameraGlideTest, TheGlideDependsOnTimeNotOnFrames) {
  CameraRig fast = switchedToAiming();
  CameraRig slow = switchedToAiming();
  CameraRig uneven = switchedToAiming();
  for (int i = 0; i < 24; ++i) fast.update(0.25 * kGlideTime / 24);
  slow.update(0.25 * kGlideTime);
  for (const double part : {0.1, 0.02, 0.13}) uneven.update(part * kGlideTime);
  EXPECT_LT(gap(fast.view(), slow.view()), 1e-9);
  EXPECT_LT(gap(uneven.view(), slow.view()), 1e-9);
}

TEST(CameraGlideTest, HeldTheViewStaysAndReleasedItGlidesOn) {
  CameraRig rig = switchedToAiming();
  rig.update(kGlideTime);
  const ViewPoint before = rig.view();
  rig.hold(true);
  rig.followCue(Eigen::Vector3d(0.4, -0.3, kRadius), 1.0);  // the ball moved under the cursor
  rig.update(1.0);
  EXPECT_LT(gap(rig.view(), before), 1e-12);
  rig.hold(false);
  EXPECT_LT(gap(rig.view(), before), 1e-12);  // no cut on release either
  rig.update(kGlideTime);
  EXPECT_LT(gap(rig.view(), rig.goal()), 1e-12);
  EXPECT_LT((rig.view().target - Eigen::Vector3d(0.4, -0.3, kRadius)).norm(), 1e-12);
}

/// The corners (±x, ±y) of the table plane drawn by `camera` in a 1280 × 720 window, left of
/// `right_edge` px.
void expectCornersWithin(const render::Camera& camera, float x, float y, float right_edge) {
  for (float sx : {-x, x}) {
    for (float sy : {-y, y}) {
      const glm::vec3 p = render::projectToPixels(camera, 1280, 720, glm::vec3(sx, sy, 0.0f));
      EXPECT_GT(p.x, 0.0f);
      EXPECT_LT(p.x, right_edge);
      EXPECT_GT(p.y, 0.0f);
      EXPECT_LT(p.y, 720.0f);
    }
  }
}

TEST(CameraGlideTest, OverheadLooksDownOnTheWholeTable) {
  CameraRig rig(2.54, 1.27, 1280.0 / 720.0);
  rig.setOverhead(true);
  rig.update(kGlideTime);
  const ViewPoint view = rig.view();
  const Eigen::Vector3d down = (view.target - view.eye).normalized();
  EXPECT_LT(down.z(), -0.999);  // within 2.6° of straight down
  const auto camera = cameraOf(view);
  // The rails' outer corners (about 15 cm beyond the playing surface).
  expectCornersWithin(camera, 1.42f, 0.78f, 1280.0f);
}

TEST(CameraGlideTest, TheOverheadViewZoomsAndPansAndOStartsItAfresh) {
  CameraRig rig(2.54, 1.27, 1280.0 / 720.0);
  rig.setOverhead(true);
  rig.settle();
  const ViewPoint whole = rig.view();
  // S / X / the wheel: the distance by the factor given (the view still straight down).
  rig.zoom(0.5);
  rig.settle();
  EXPECT_NEAR((rig.view().eye - rig.view().target).norm(), 0.5 * (whole.eye - whole.target).norm(),
              1e-9);
  EXPECT_LT((rig.view().target - whole.target).norm(), 1e-12);
  // Orbit and raise pan it across the screen: + moves the view right (+x here, the table
  // lengthwise across) and up (+y), by kOverheadPan × the view's distance per radian.
  const double distance = (rig.view().eye - rig.view().target).norm();
  rig.orbit(0.2);
  rig.raise(-0.1);
  rig.settle();
  const Eigen::Vector3d moved = rig.view().target - whole.target;
  EXPECT_NEAR(moved.x(), 0.2 * kOverheadPan * distance, 1e-9);
  EXPECT_NEAR(moved.y(), -0.1 * kOverheadPan * distance, 1e-9);
  EXPECT_NEAR(moved.z(), 0.0, 1e-12);
  // O off and on again: the whole table, neither zoomed nor panned.
  rig.setOverhead(false);
  rig.setOverhead(true);
  rig.settle();
  EXPECT_LT((rig.view().eye - whole.eye).norm(), 1e-12);
  EXPECT_LT((rig.view().target - whole.target).norm(), 1e-12);
}

TEST(CameraGlideTest, TheOverheadViewFramesTheTableInTheClearArea) {
  // Clear only in the window's left half (a pane over the right): the table turns lengthwise up
  // the screen (it fits larger so) with its head end at the bottom, centred in that half.
  CameraRig rig(2.54, 1.27, 1280.0 / 720.0);
  rig.setClearArea({0.0, 0.0, 0.5, 1.0});
  rig.setOverhead(true);
  rig.settle();
  const auto camera = cameraOf(rig.view());
  const glm::vec3 head = render::projectToPixels(camera, 1280, 720, glm::vec3(-1.27f, 0, 0));
  const glm::vec3 foot = render::projectToPixels(camera, 1280, 720, glm::vec3(1.27f, 0, 0));
  const glm::vec3 centre = render::projectToPixels(camera, 1280, 720, glm::vec3(0, 0, 0));
  EXPECT_GT(head.y, foot.y) << "the head end at the bottom";
  // Lengthwise up the screen: within 1 % of its 600 px (the view leans 1.2° off vertical, so a
  // line off its centre converges a little).
  EXPECT_NEAR(head.x, foot.x, 6.0) << "lengthwise up the screen";
  EXPECT_NEAR(centre.x, 320.0, 3.0);
  EXPECT_NEAR(centre.y, 360.0, 3.0);
  expectCornersWithin(camera, 1.27f, 0.635f, 640.0f);
}

TEST(CameraGlideTest, TheWatchingViewChasesTheCueBallEasedAndStaysWhenLetGo) {
  CameraRig rig(2.54, 1.27, 1280.0 / 720.0);
  const Eigen::Vector3d start = rig.watching().target;
  const Eigen::Vector3d ball(0.9, 0.4, kRadius);
  rig.chase(ball);
  // 1 s at 60 Hz: the look-at point closes 1 − e^(−3) = 95 % of the way (the eye keeps its
  // offset from it: an orbit).
  for (int i = 0; i < 60; ++i) rig.update(1.0 / 60.0);
  const double closed = 1.0 - (rig.watching().target - ball).norm() / (start - ball).norm();
  EXPECT_NEAR(closed, 1.0 - std::exp(-3.0), 1e-9);
  // Let go: it stays where it got to.
  rig.chase(std::nullopt);
  const Eigen::Vector3d kept = rig.watching().target;
  for (int i = 0; i < 30; ++i) rig.update(1.0 / 60.0);
  EXPECT_LT((rig.watching().target - kept).norm(), 1e-12);
  // Aiming, nothing is chased.
  rig.setAiming(true);
  rig.chase(Eigen::Vector3d(-1.0, -0.5, kRadius));
  for (int i = 0; i < 30; ++i) rig.update(1.0 / 60.0);
  EXPECT_LT((rig.watching().target - kept).norm(), 1e-12);
}

TEST(CameraGlideTest, BGoesBackBehindTheCueAndOLooksDown) {
  Controls controls = nineFootControls();
  controls.startTurn(Eigen::Vector3d(-0.5, 0.1, kRadius), rules::BallInHand::None);
  hold(controls, Key::Left, 0.5, {.shift = true});  // orbit the aiming view
  hold(controls, Key::Up, 0.5);                     // and raise it
  hold(controls, Key::O, 0.1);
  EXPECT_TRUE(controls.camera().overhead());
  controls.keyDown(Key::B, {});
  controls.keyUp(Key::B);
  EXPECT_TRUE(controls.camera().gliding());
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  EXPECT_FALSE(controls.camera().overhead());
  const ViewPoint view = controls.camera().view();
  const Eigen::Vector2d back = (view.eye - view.target).head<2>().normalized();
  const double yaw = controls.aim().yaw;
  EXPECT_NEAR(back.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw))), -1.0, 1e-9);
  EXPECT_NEAR(controls.camera().aimingOrbit().elevation,
              CameraRig(2.54, 1.27, 1.0).aimingOrbit().elevation, 1e-12);
}

}  // namespace
}  // namespace pool::app::test
