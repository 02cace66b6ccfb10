// A snooker table in real frames: the balls' colours and the chalked baulk line, D and spots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/screenshot_fixture.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

/// The hue classes a snooker ball's pixel falls in, read from its channels' proportions (so a
/// ball in a lamp's pool and one in the hall's dimmer light class alike).
enum class Hue { White, Black, Red, Pink, Yellow, Other };

const char* nameOf(Hue h) {
  switch (h) {
    case Hue::White:
      return "white";
    case Hue::Black:
      return "black";
    case Hue::Red:
      return "red";
    case Hue::Pink:
      return "pink";
    case Hue::Yellow:
      return "yellow";
    case Hue::Other:
      break;
  }
  return "other";
}

Hue hueOf(const Rgb& p) {
  const double r = p[0], g = p[1], b = p[2];
  const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
  if (hi < 45) return Hue::Black;
  if (lo > 120 && hi - lo < 45) return Hue::White;
  if (r < 50 || r < hi) return Hue::Other;
  if (g < 0.25 * r && b < 0.25 * r) return Hue::Red;  // a deep red: hardly any green or blue
  if (g > 0.6 * r && b < 0.35 * r) return Hue::Yellow;
  // Pink: red lightened toward white, with more blue than green (not orange, not brown).
  if (g > 0.3 * r && b > 0.4 * r && b > g && b < 0.9 * r) return Hue::Pink;
  return Hue::Other;
}

/// The class most of the 5 × 5 pixels around `px` fall in, and how many do.
std::pair<Hue, int> majorityHue(const Image& image, glm::vec3 px) {
  int counts[6] = {};
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) {
      ++counts[static_cast<int>(hueOf(image.at(int(px.x) + dx, int(px.y) + dy)))];
    }
  }
  int best = 0;
  for (int h = 1; h < 6; ++h) {
    if (counts[h] > counts[best]) best = h;
  }
  return {static_cast<Hue>(best), counts[best]};
}

/// The brightest luminance within `reach` pixels of `px` (a line a pixel wide may fall between
/// two columns).
double peakLuminance(const Image& image, glm::vec3 px, int reach) {
  double best = 0;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      best = std::max(best, luminance(image.at(int(px.x) + dx, int(px.y) + dy)));
    }
  }
  return best;
}

struct Placed {
  int id;
  double x, y;
  Hue hue;
};

class RenderSnookerTest : public ScreenshotInfoTest {
 protected:
  void SetUp() override {
    ScreenshotInfoTest::SetUp();
    auto spec = table::loadTableSpec("snooker-12ft");
    ASSERT_TRUE(spec) << spec.error();
    ASSERT_TRUE(spec->snooker_marks.has_value());
    spec_ = *spec;
    // The marks from the spec's own figures (Rules of Snooker, Section 1): baulk is the −x end.
    baulk_x_ = -spec_.length / 2 + spec_.snooker_marks->baulk_line;
    d_radius_ = spec_.snooker_marks->d_radius;
  }

  /// Renders the table with the cue ball and the balls of `balls` (id 0 first) seen from above.
  Image render(const std::vector<Placed>& balls, const std::string& extra = "") {
    std::string flags = "--table snooker-12ft --scene top " + extra;
    char buf[96];
    for (const Placed& b : balls) {
      if (b.id == 0) {
        std::snprintf(buf, sizeof buf, " --cue-at %.4f %.4f", b.x, b.y);
        flags += buf;
      }
    }
    flags += " --balls";
    for (const Placed& b : balls) {
      if (b.id == 0) continue;
      std::snprintf(buf, sizeof buf, " %d %.4f %.4f", b.id, b.x, b.y);
      flags += buf;
    }
    return view(flags);
  }

  /// The chalk at table point (x, y) is lighter than the felt `off` metres either side along x
  /// (across the baulk line; the D and the spots are seen across x too).
  void expectChalk(const Image& image, double x, double y, double off, double ratio,
                   const char* what) {
    const glm::vec3 on = camera_.pixel(glm::vec3(float(x), float(y), 0.0f));
    ASSERT_TRUE(camera_.inside(on, 4.0f)) << what;
    const double mark = peakLuminance(image, on, 1);
    for (const double side : {-off, off}) {
      const glm::vec3 beside = camera_.pixel(glm::vec3(float(x + side), float(y), 0.0f));
      const double felt = peakLuminance(image, beside, 1);
      EXPECT_GT(mark, ratio * felt) << what << " at (" << x << ", " << y << "): " << mark
                                    << ", felt " << side << " m away " << felt;
    }
  }

  table::TableSpec spec_;
  double baulk_x_ = 0, d_radius_ = 0;
};

// A red, the pink, the black, the yellow and the cue ball (in the D), each where the test puts
// it, none on a mark; the sidecar's camera projects their tops.
const std::vector<Placed> kBalls = {{0, -1.2, -0.15, Hue::White},
                                    {5, 0.3, 0.45, Hue::Red},
                                    {20, 1.0, -0.35, Hue::Pink},
                                    {21, 1.45, 0.3, Hue::Black},
                                    {16, -0.55, -0.5, Hue::Yellow}};

TEST_F(RenderSnookerTest, EachBallShowsItsSnookerColour) {
  const Image image = render(kBalls);
  ASSERT_EQ(image.width, camera_.width);
  ASSERT_EQ(camera_.mirrored(), "");
  const double r = spec_.params.ball_radius;
  for (const Placed& b : kBalls) {
    const glm::vec3 px = camera_.pixel(glm::vec3(float(b.x), float(b.y), float(2 * r)));
    ASSERT_TRUE(camera_.inside(px, 4.0f)) << "ball " << b.id;
    const auto [hue, n] = majorityHue(image, px);
    const Rgb& centre = image.at(int(px.x), int(px.y));
    EXPECT_EQ(nameOf(hue), std::string(nameOf(b.hue)))
        << "ball " << b.id << ": " << n << " of 25 pixels " << nameOf(hue) << "; the centre's "
        << centre[0] << ", " << centre[1] << ", " << centre[2];
    EXPECT_GE(n, 13) << "ball " << b.id;
  }
}

TEST_F(RenderSnookerTest, TheBaulkLineTheDAndTheSpotsAreChalkedOnTheFelt) {
  const Image image = render(kBalls);
  ASSERT_EQ(image.width, camera_.width);
  // The baulk line, clear of the D and the balls, on both sides of the table.
  for (const double y : {-0.7, -0.45, 0.45, 0.7}) {
    expectChalk(image, baulk_x_, y, 0.012, 1.25, "baulk line");
  }
  // The D's back, on the table's axis, and its arc 45° off it.
  const double c = std::cos(std::numbers::pi / 4), s = std::sin(std::numbers::pi / 4);
  expectChalk(image, baulk_x_ - d_radius_, 0.0, 0.012, 1.25, "the D's back");
  expectChalk(image, baulk_x_ - d_radius_ * c, d_radius_ * s, 0.012, 1.2, "the D's arc");
  // The blue spot at the centre; the black's, 324 mm from the top cushion (no ball on either).
  expectChalk(image, 0.0, 0.0, 0.015, 1.25, "blue spot");
  expectChalk(image, spec_.length / 2 - spec_.snooker_marks->black_spot, 0.0, 0.015, 1.25,
              "black spot");
  // The other half of the table at the baulk line's mirror: no line there.
  const glm::vec3 mirror = camera_.pixel(glm::vec3(float(-baulk_x_), 0.6f, 0.0f));
  const glm::vec3 beside = camera_.pixel(glm::vec3(float(-baulk_x_ + 0.012), 0.6f, 0.0f));
  EXPECT_LT(peakLuminance(image, mirror, 1), 1.08 * peakLuminance(image, beside, 1))
      << "a lighter line where no mark is";
  // No mark in front of the D (the baulk side only): on the axis, a D's radius up the table.
  const glm::vec3 ahead = camera_.pixel(glm::vec3(float(baulk_x_ + d_radius_), 0.0f, 0.0f));
  const glm::vec3 ahead_beside =
      camera_.pixel(glm::vec3(float(baulk_x_ + d_radius_ + 0.012), 0.0f, 0.0f));
  EXPECT_LT(peakLuminance(image, ahead, 1), 1.08 * peakLuminance(image, ahead_beside, 1))
      << "the D is drawn on the baulk side only";
}

TEST_F(RenderSnookerTest, TheBaulkLineShowsInTheLightPreset) {
  const Image image = render(kBalls, "--quality light");
  ASSERT_EQ(image.width, camera_.width);
  for (const double y : {-0.6, 0.6}) {
    expectChalk(image, baulk_x_, y, 0.015, 1.2, "baulk line (light preset)");
  }
}

TEST_F(RenderSnookerTest, APoolTableHasNoMarks) {
  // The same top view of the 9-ft pool table: nothing lighter across the felt where a snooker
  // table's baulk line would be (scaled to its length).
  const Image image = view("--scene top --cue-at -1.0 0.3 --balls 3 0.3 0.2");
  ASSERT_EQ(image.width, camera_.width);
  const auto pool = table::loadTableSpec("wpa-9ft");
  ASSERT_TRUE(pool) << pool.error();
  const double x = baulk_x_ / spec_.length * pool->length;
  for (const double y : {-0.45, 0.45}) {
    const glm::vec3 at = camera_.pixel(glm::vec3(float(x), float(y), 0.0f));
    const glm::vec3 beside = camera_.pixel(glm::vec3(float(x + 0.012), float(y), 0.0f));
    EXPECT_LT(peakLuminance(image, at, 1), 1.08 * peakLuminance(image, beside, 1)) << y;
  }
}

}  // namespace
}  // namespace pool::client::test
