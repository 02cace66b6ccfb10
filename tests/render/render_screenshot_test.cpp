// pool-client --screenshot under Xvfb and through EGL without a display: the racked table (felt,
// cushions, rails, sixteen numbered balls where the reported camera, checked to be an unmirrored
// overview, puts them) and the P/T/L switches (wireframe, textures, lighting).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "support/png_image.h"
#include "support/screenshot_fixture.h"
#include "support/xvfb_run.h"

namespace pool::client::test {
namespace {

using RenderScreenshotTest = ScreenshotInfoTest;

constexpr Rgb kFelt{0.05, 0.42, 0.20};
constexpr Rgb kWood{0.34, 0.17, 0.07};
constexpr int kWidth = 1280;
constexpr int kHeight = 720;

/// A ball's centre and radius in the screenshot.
struct BallOnScreen {
  int id = 0;
  double x = 0, y = 0, radius = 0;
};

/// The overview the screenshot promises, checked on the camera it reports rather than taken from
/// the camera code: no mirror, from above the table's near (−y) side, the table's length (+x)
/// across the image to the right and its far side up.
void expectOverview(const ReportedCamera& camera) {
  EXPECT_EQ(camera.mirrored(), "");
  EXPECT_LT(camera.eye.y, 0.0f) << "seen from the near side";
  EXPECT_GT(camera.eye.z, 0.5f) << "seen from above";
  EXPECT_GT(camera.right().x, 0.99f) << "+x to the right";
  EXPECT_GT(camera.up().y, 0.0f) << "the far side up";
  const glm::vec3 foot = camera.pixel(glm::vec3(1.0f, 0.0f, 0.0f));
  const glm::vec3 head = camera.pixel(glm::vec3(-1.0f, 0.0f, 0.0f));
  EXPECT_GT(foot.x, head.x + 100.0f) << "the foot end drawn right of the head end";
}

/// The rack's balls (from the scene, not from what was drawn) where `camera` puts them.
std::vector<BallOnScreen> rackOnScreen(const ReportedCamera& camera) {
  auto scene = render::rackScene();
  EXPECT_TRUE(static_cast<bool>(scene));
  if (!scene) return {};
  // A point one radius to the side (across the view) gives the ball's radius on screen.
  const glm::vec3 side = camera.right() * float(scene->ball_radius);
  std::vector<BallOnScreen> out;
  for (const auto& b : scene->balls) {
    const glm::vec3 c(b.pos.x(), b.pos.y(), b.pos.z());
    const glm::vec3 centre = camera.pixel(c);
    const glm::vec3 edge = camera.pixel(c + side);
    out.push_back({b.id, centre.x, centre.y, glm::length(glm::vec2(edge) - glm::vec2(centre))});
  }
  return out;
}

// Outside the lamps' pools the felt, cushions and rails lie in the hall's dim light.
constexpr double kDim = 24.0;
const auto kIsFelt = [](const Rgb& p) { return shadeOf(p, kFelt, kDim); };

TEST_F(RenderScreenshotTest, RackSceneShowsFeltCushionsRailsAndSixteenBalls) {
  const Image image = view("--scene rack");
  expectOverview(camera_);
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  const int total = image.width * image.height;
  EXPECT_GT(count(image, kIsFelt), total * 35 / 100) << "felt green should fill much of the frame";

  const auto wood = [](const Rgb& p) { return shadeOf(p, kWood, kDim); };
  EXPECT_GT(count(image, wood, 0, image.width / 4), 2000) << "wooden rail on the left";
  EXPECT_GT(count(image, wood, image.width * 3 / 4), 2000) << "wooden rail on the right";

  // Each cushion's top, just behind its nose, is cloth-covered (green), not wood or background.
  auto scene = render::rackScene();
  ASSERT_TRUE(static_cast<bool>(scene));
  int cushions = 0;
  for (const auto& nose : scene->geometry.noses) {
    if (nose.name.rfind("jaw", 0) == 0) continue;
    const Eigen::Vector2d behind = (nose.a + nose.b) / 2.0 - nose.normal * 0.02;
    const glm::vec3 px =
        camera_.pixel(glm::vec3(behind.x(), behind.y(), scene->geometry.nose_height + 0.004));
    ++cushions;
    EXPECT_GE(countInDisc(image, px.x, px.y, 3.0, kIsFelt), 20) << "cushion " << nose.name;
  }
  EXPECT_EQ(cushions, 6);

  // Sixteen balls, each showing its own colour where the camera projects it.
  const auto balls = rackOnScreen(camera_);
  ASSERT_EQ(balls.size(), 16u);
  for (const BallOnScreen& b : balls) {
    ASSERT_GT(b.radius, 4.0);
    const int own = countInDisc(image, b.x, b.y, b.radius * 0.85,
                                [&](const Rgb& p) { return ballColour(b.id, p); });
    EXPECT_GE(own, 8) << "ball " << b.id << " at (" << b.x << ", " << b.y << ")";
  }
}

TEST_F(RenderScreenshotTest, NumbersShowAsWhiteCirclesOnColouredBallsUnlessTexturesAreOff) {
  const Image textured = view("--scene rack");
  const Image plain = screenshot("--scene rack --no-textures");
  ASSERT_EQ(textured.width, kWidth);
  ASSERT_EQ(plain.width, kWidth);
  expectOverview(camera_);
  for (const BallOnScreen& b : rackOnScreen(camera_)) {
    if (b.id < 1 || b.id > 7) continue;  // solids: white can only be the number circle
    const int with = countInDisc(textured, b.x, b.y, b.radius * 0.5, isWhite);
    const int without = countInDisc(plain, b.x, b.y, b.radius * 0.5, isWhite);
    EXPECT_GE(with, 4) << "number circle on ball " << b.id;
    EXPECT_GE(with, without + 4) << "ball " << b.id << " without textures";
  }
}

TEST_F(RenderScreenshotTest, WireframeShowsTheBackgroundThroughTheTable) {
  const Image solid = screenshot("--scene rack");
  const Image wire = screenshot("--scene rack --wireframe");
  ASSERT_EQ(wire.width, kWidth);
  const int solid_felt = count(solid, kIsFelt);
  const int wire_felt = count(wire, kIsFelt);
  EXPECT_LT(wire_felt, solid_felt / 4) << "only the felt's edges are drawn";
  const auto background = [](const Rgb& p) {
    return std::abs(p[0] - 25.5) < 3 && std::abs(p[1] - 25.5) < 3 && std::abs(p[2] - 30.6) < 3;
  };
  // The middle of the table: felt when solid, mostly background when wireframe.
  const int middle = countInDisc(wire, kWidth / 2.0, kHeight / 2.0, 60.0, background);
  EXPECT_GT(middle, 60 * 60 * 3 / 2) << "background shows through the felt";
  EXPECT_EQ(countInDisc(solid, kWidth / 2.0, kHeight / 2.0, 60.0, background), 0);
}

TEST_F(RenderScreenshotTest, WithoutLightingTheFeltIsOneFlatColour) {
  const Image lit = screenshot("--scene rack --no-textures");
  const Image unlit = screenshot("--scene rack --no-textures --no-lighting");
  ASSERT_EQ(unlit.width, kWidth);
  // Unlit: the felt albedo itself, everywhere on the playing surface.
  const auto albedo = [](const Rgb& p) {
    return std::abs(p[0] - kFelt[0] * 255) < 2.5 && std::abs(p[1] - kFelt[1] * 255) < 2.5 &&
           std::abs(p[2] - kFelt[2] * 255) < 2.5;
  };
  const int total = kWidth * kHeight;
  EXPECT_GT(count(unlit, albedo), total * 30 / 100);
  // Lit: the spotlights brighten the felt under the lamps well above its far corners.
  EXPECT_LT(count(lit, albedo), total / 20);
}

TEST_F(RenderScreenshotTest, WithoutDisplayEglRendersTheSameRack) {
  const Image xvfb = screenshot("--scene rack");
  const std::string cmd = std::string("env -u DISPLAY -u WAYLAND_DISPLAY ") + POOL_BIN_DIR +
                          "/pool-client --screenshot " + png_ + " --scene rack";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const Image egl = loadPng(png_);
  ASSERT_EQ(egl.width, kWidth);
  ASSERT_EQ(xvfb.width, kWidth);
  int same = 0;
  for (std::size_t i = 0; i < egl.pixels.size(); ++i) {
    const Rgb& a = egl.pixels[i];
    const Rgb& b = xvfb.pixels[i];
    if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) <= 6) ++same;
  }
  EXPECT_GT(same, kWidth * kHeight * 99 / 100);
  EXPECT_GT(count(egl, kIsFelt), kWidth * kHeight * 35 / 100);
}

TEST_F(RenderScreenshotTest, FramesOptionStillWritesOnePng) {
  const Image image = screenshot("--frames 1");
  EXPECT_EQ(image.width, kWidth);
  EXPECT_EQ(image.height, kHeight);
}

TEST_F(RenderScreenshotTest, UnknownSceneIsRefusedWithoutWritingAFile) {
  const std::string cmd = pool::test::xvfbRun() + std::string(" ") + POOL_BIN_DIR +
                          "/pool-client --screenshot " + png_ + " --scene nowhere 2>/dev/null";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  EXPECT_EQ(loadPng(png_).width, 0);
}

}  // namespace
}  // namespace pool::client::test
