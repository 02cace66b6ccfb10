// pool-client --screenshot --scene rack under Xvfb: felt, wooden rails and all sixteen balls.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

/// An RGB image decoded from a PNG (empty when the file could not be read).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::array<double, 3>> pixels;  ///< row-major, top row first, 0..255
};

Image loadPng(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  if (!data) return image;
  const auto n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  for (std::size_t i = 0; i < n; ++i)
    image.pixels.push_back({double(data[3 * i]), double(data[3 * i + 1]), double(data[3 * i + 2])});
  stbi_image_free(data);
  return image;
}

/// True when `p` is a lit shade of `colour`: same hue and saturation (direction in RGB), bright
/// enough.
bool shadeOf(const std::array<double, 3>& p, const std::array<double, 3>& colour) {
  double dot = 0, pp = 0, cc = 0;
  for (int i = 0; i < 3; ++i) {
    dot += p[i] * colour[i];
    pp += p[i] * p[i];
    cc += colour[i] * colour[i];
  }
  const double brightest = std::max({p[0], p[1], p[2]});
  return brightest >= 40.0 && dot / std::sqrt(pp * cc) > 0.997;
}

bool isWhite(const std::array<double, 3>& p) {
  return std::min({p[0], p[1], p[2]}) > 190.0 &&
         std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) < 30.0;
}

bool isBlack(const std::array<double, 3>& p) {
  return std::max({p[0], p[1], p[2]}) < 20.0;
}

/// Pixels of `image` (optionally within columns [x0, x1)) satisfying `pred`.
template <class Pred>
int count(const Image& image, Pred pred, int x0 = 0, int x1 = -1) {
  if (x1 < 0) x1 = image.width;
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (pred(image.pixels[static_cast<std::size_t>(y * image.width + x)])) ++n;
    }
  }
  return n;
}

constexpr std::array<double, 3> kFelt{0.05, 0.42, 0.20};
constexpr std::array<double, 3> kWood{0.34, 0.17, 0.07};

struct NamedColour {
  const char* name;
  std::array<double, 3> rgb;
};

/// Ball colours 1–7 (each also the band of the stripe n + 8).
constexpr std::array<NamedColour, 7> kBallColours{{
    {"yellow", {0.98, 0.80, 0.05}},
    {"blue", {0.05, 0.15, 0.80}},
    {"red", {0.85, 0.05, 0.05}},
    {"purple", {0.40, 0.10, 0.60}},
    {"orange", {1.00, 0.45, 0.02}},
    {"green", {0.02, 0.55, 0.08}},
    {"maroon", {0.45, 0.04, 0.10}},
}};

class RenderScreenshotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
      GTEST_SKIP() << "xvfb-run is not installed";
    png_ = "/tmp/pool-render-test-" + std::to_string(::getpid()) + ".png";
  }
  void TearDown() override {
    if (!png_.empty() && !std::getenv("POOL_KEEP_TEST_FILES")) std::remove(png_.c_str());
  }
  int screenshot(const std::string& extra) const {
    const std::string cmd = std::string("xvfb-run -a -s \"-screen 0 1280x720x24\" ") +
                            POOL_BIN_DIR + "/pool-client --screenshot " + png_ + " " + extra;
    return std::system(cmd.c_str());
  }
  std::string png_;
};

TEST_F(RenderScreenshotTest, RackSceneShowsFeltRailsAndSixteenBalls) {
  ASSERT_EQ(screenshot("--scene rack"), 0);
  const Image image = loadPng(png_);
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(image.height, 720);
  const int total = image.width * image.height;

  const auto felt = [](const auto& p) { return shadeOf(p, kFelt); };
  EXPECT_GT(count(image, felt), total * 35 / 100) << "felt green should fill much of the frame";

  const auto wood = [](const auto& p) { return shadeOf(p, kWood); };
  EXPECT_GT(count(image, wood, 0, image.width / 4), 2000) << "wooden rail on the left";
  EXPECT_GT(count(image, wood, image.width * 3 / 4), 2000) << "wooden rail on the right";

  for (const NamedColour& c : kBallColours) {
    EXPECT_GE(count(image, [&](const auto& p) { return shadeOf(p, c.rgb); }), 40)
        << c.name << " balls";
  }
  EXPECT_GE(count(image, isWhite), 60) << "cue ball and stripes";
  EXPECT_GE(count(image, isBlack), 40) << "8 ball (and pockets)";
}

TEST_F(RenderScreenshotTest, FramesOptionStillWritesOnePng) {
  ASSERT_EQ(screenshot("--frames 1"), 0);
  const Image image = loadPng(png_);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
}

}  // namespace
