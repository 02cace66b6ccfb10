// When a lamp's shade fades from a view: never for its size alone; over a point of the shot it
// must not hide (farther from the eye than the shade, seen within its disc); when the eye comes
// up to the shade; from a view straight down over the lamps. The geometry is the test's own: a
// camera looking along +x at the shade's height, the shade's disc where the projection puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "client/render/camera.h"
#include "client/render/lamps.h"

namespace pool::render {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
const glm::vec3 kLamp(0.6f, 0.0f, kLampHeight);

/// An eye `back` m behind the lamp along −x at the shade's height, looking along +x.
Camera levelCamera(float back) {
  const glm::vec3 eye = kLamp - glm::vec3(back, 0.0f, 0.0f);
  return {eye, eye + glm::vec3(1.0f, 0.0f, 0.0f), 40.0f};
}

TEST(LampOpacityTest, AShadeFillingMuchOfTheViewIsDrawnWhole) {
  const Camera camera = levelCamera(1.0f);
  const auto disc = shadeDisc(camera, kWidth, kHeight, kLamp);
  ASSERT_TRUE(disc.has_value());
  // About a sixth of the view's height in radius: far past the old 3 % of the view.
  EXPECT_GT(3.14159f * disc->radius * disc->radius, 0.05f * kWidth * kHeight);
  EXPECT_EQ(lampOpacity(camera, kWidth, kHeight, kLamp), 1.0f);
}

TEST(LampOpacityTest, AShadeBeforeAPointOfTheShotFadesAndOneAsideDoesNot) {
  const Camera camera = levelCamera(1.0f);
  // Straight behind the shade, 1 m beyond it: hidden, so the shade goes.
  const std::vector<glm::vec3> behind{kLamp + glm::vec3(1.0f, 0.0f, -0.02f)};
  EXPECT_EQ(lampOpacity(camera, kWidth, kHeight, kLamp, behind), 0.0f);
  // The same point between the eye and the shade is drawn over it: the shade stays.
  const std::vector<glm::vec3> before{kLamp - glm::vec3(0.5f, 0.0f, 0.02f)};
  EXPECT_EQ(lampOpacity(camera, kWidth, kHeight, kLamp, before), 1.0f);
  // Far to the side of the disc (1 m left at 2 m: ~27° off the axis, the disc ~8° round it).
  const std::vector<glm::vec3> aside{kLamp + glm::vec3(1.0f, 1.0f, 0.0f)};
  EXPECT_EQ(lampOpacity(camera, kWidth, kHeight, kLamp, aside), 1.0f);
  // Just outside the disc's edge, within the margin and the fade: partly faded, never whole.
  const auto disc = shadeDisc(camera, kWidth, kHeight, kLamp);
  ASSERT_TRUE(disc.has_value());
  const float pixel_angle = glm::radians(40.0f) / kHeight;  // about, near the centre
  const float edge = (disc->radius + kClearMargin + 0.25f * kClearFade * disc->radius) *
                     pixel_angle * 2.0f;  // m across at 2 m from the eye
  const std::vector<glm::vec3> near_edge{kLamp + glm::vec3(1.0f, edge, 0.055f)};
  const float partly = lampOpacity(camera, kWidth, kHeight, kLamp, near_edge);
  EXPECT_GT(partly, 0.0f);
  EXPECT_LT(partly, 1.0f);
}

TEST(LampOpacityTest, TheShadeFadesAsTheEyeComesUpToIt) {
  EXPECT_EQ(lampOpacity(levelCamera(0.7f), kWidth, kHeight, kLamp), 1.0f);
  EXPECT_EQ(lampOpacity(levelCamera(0.3f), kWidth, kHeight, kLamp), 0.0f);
  const float between = lampOpacity(levelCamera(0.5f), kWidth, kHeight, kLamp);
  EXPECT_GT(between, 0.0f);
  EXPECT_LT(between, 1.0f);
}

TEST(LampOpacityTest, AViewStraightDownFromOverTheLampsHasNone) {
  const Camera top{glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f, 0.0f, 0.0f), 40.0f,
                   glm::vec3(0.0f, 1.0f, 0.0f)};
  EXPECT_EQ(lampOpacity(top, kWidth, kHeight, kLamp), 0.0f);
  // The same eye looking down at 45°: the lamps hang in view.
  const Camera slanted{glm::vec3(0.0f, -2.0f, 3.0f), glm::vec3(0.0f, 1.0f, 0.0f), 40.0f};
  EXPECT_EQ(lampOpacity(slanted, kWidth, kHeight, kLamp), 1.0f);
}

}  // namespace
}  // namespace pool::render
