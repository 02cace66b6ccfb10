// The screenshot sidecar's points: a pixel for each point in front of the camera, none for a point
// behind it (it was reported at pixel (0, 0)), and whether the image shows it.
#include "client/render/screenshot_info.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace pool::render {
namespace {

Camera lookingAlongX() {
  Camera c;
  c.eye = {0.0f, 0.0f, 1.0f};
  c.target = {1.0f, 0.0f, 1.0f};
  c.up = {0.0f, 0.0f, 1.0f};
  c.fov_y_deg = 60.0f;
  return c;
}

TEST(ScreenshotInfoTest, APointAheadHasItsPixelAndOneBehindHasNone) {
  const Camera camera = lookingAlongX();
  // Straight ahead: the middle of a 640 × 480 image (0.01 px of rounding).
  const auto ahead = pointJson(camera, 640, 480, {2.0f, 0.0f, 1.0f});
  EXPECT_TRUE(ahead.at("on_screen").get<bool>());
  EXPECT_NEAR(ahead.at("px")[0].get<double>(), 320.0, 0.01);
  EXPECT_NEAR(ahead.at("px")[1].get<double>(), 240.0, 0.01);
  // Behind the eye: no pixel, not on screen.
  const auto behind = pointJson(camera, 640, 480, {-2.0f, 0.0f, 1.0f});
  EXPECT_TRUE(behind.at("px").is_null());
  EXPECT_FALSE(behind.at("on_screen").get<bool>());
  // Ahead but far to the left, outside the 60° × 80° view: a pixel left of the image.
  const auto aside = pointJson(camera, 640, 480, {1.0f, 5.0f, 1.0f});
  ASSERT_TRUE(aside.at("px").is_array());
  EXPECT_LT(aside.at("px")[0].get<double>(), 0.0);
  EXPECT_FALSE(aside.at("on_screen").get<bool>());
}

}  // namespace
}  // namespace pool::render
