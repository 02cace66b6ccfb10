// The default camera frames the whole table; pixel rays invert the renderer's projection.
#include "client/app/camera_rig.h"

#include <gtest/gtest.h>

#include "app_fixture.h"

namespace pool::app::test {
namespace {

TEST(CameraRigTest, TheDefaultViewFramesTheWholeTable) {
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1024, 768}, std::pair{720, 1000}}) {
    const CameraRig rig(2.54, 1.27, static_cast<double>(w) / h);
    const auto camera = cameraOf(rig.view());
    // The rails' outer corners (about 15 cm beyond the playing surface).
    for (float x : {-1.42f, 1.42f}) {
      for (float y : {-0.78f, 0.78f}) {
        const glm::vec3 p = render::projectToPixels(camera, w, h, glm::vec3(x, y, 0.0f));
        EXPECT_GT(p.x, 0.0f) << w << "x" << h << " corner " << x << "," << y;
        EXPECT_LT(p.x, static_cast<float>(w));
        EXPECT_GT(p.y, 0.0f);
        EXPECT_LT(p.y, static_cast<float>(h));
      }
    }
  }
}

TEST(CameraRigTest, ARayUnderAPixelHitsThePointProjectedThere) {
  CameraRig rig(2.54, 1.27, 1280.0 / 720.0);
  rig.orbit(0.7);
  rig.raise(-0.3);
  const ViewPoint view = rig.view();
  for (const Eigen::Vector2d& at :
       {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, -0.5), Eigen::Vector2d(-1.1, 0.4)}) {
    const glm::vec3 p = render::projectToPixels(
        cameraOf(view), 1280, 720,
        glm::vec3(static_cast<float>(at.x()), static_cast<float>(at.y()), kRadius));
    const auto hit = pointUnderPixel(view, 1280, 720, p.x, p.y, kRadius);
    ASSERT_TRUE(hit);
    EXPECT_LT((*hit - at).norm(), 2e-3) << at.transpose();
  }
}

TEST(CameraRigTest, ARayAboveTheHorizonMissesTheTable) {
  CameraRig rig(2.54, 1.27, 1.0);
  rig.setAiming(true);
  rig.followCue(Eigen::Vector3d(0, 0, kRadius), 0.0);
  rig.settle();
  EXPECT_FALSE(pointUnderPixel(rig.view(), 800, 800, 400, 0, kRadius));
}

TEST(CameraRigTest, ElevationAndDistanceStayInTheirLimits) {
  CameraRig rig(2.54, 1.27, 1.5);
  const CameraLimits limits;
  rig.raise(10.0);
  EXPECT_DOUBLE_EQ(rig.watching().elevation, limits.max_elevation);
  rig.raise(-10.0);
  EXPECT_DOUBLE_EQ(rig.watching().elevation, limits.min_elevation);
  rig.zoom(1e-6);
  EXPECT_DOUBLE_EQ(rig.watching().distance, limits.min_distance);
  rig.zoom(1e9);
  EXPECT_DOUBLE_EQ(rig.watching().distance, limits.max_distance);
  EXPECT_GT(rig.view().eye.z(), 0.0);
}

}  // namespace
}  // namespace pool::app::test
