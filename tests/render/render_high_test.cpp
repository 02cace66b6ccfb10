// The high preset in real frames (llvmpipe under Xvfb): each lamp's shadow of a ball falls away
// from that lamp along the line from it; each lamp is mirrored on a ball's clear coat where the
// camera and the lamp put the reflection; the balls' outlines are anti-aliased; the felt under a
// lamp is at least half again as bright as midway between the lamps. Every expectation comes
// from the lamps' placement, the balls this test lays out and the camera the sidecar reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "client/render/lamps.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/screenshot_fixture.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

using HighPresetTest = ScreenshotInfoTest;

table::TableSpec nineFootSpec() {
  auto spec = table::loadTableSpec("wpa-9ft");
  EXPECT_TRUE(static_cast<bool>(spec));
  return *spec;
}

/// The lights over the 9-ft table: on its long axis a quarter of the length from each end, at
/// the lamps' height over the slate.
std::array<glm::dvec3, 2> lightsOver(const table::TableSpec& spec) {
  const double h = render::kLampHeight;
  return {glm::dvec3(-spec.length / 4, 0.0, h), glm::dvec3(spec.length / 4, 0.0, h)};
}

/// Mean luminance of the (2k + 1)² pixels round table point `p`.
double meanLuminance(const Image& image, const ReportedCamera& cam, glm::dvec3 p, int k = 1) {
  const glm::vec3 px = cam.pixel(glm::vec3(p));
  double sum = 0;
  for (int dy = -k; dy <= k; ++dy) {
    for (int dx = -k; dx <= k; ++dx) sum += luminance(image.at(int(px.x) + dx, int(px.y) + dy));
  }
  return sum / double((2 * k + 1) * (2 * k + 1));
}

/// The distance from `centre` to the segment a–b.
double segmentDistance(glm::dvec3 a, glm::dvec3 b, glm::dvec3 centre) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(centre - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(a + t * ab - centre);
}

/// Whether the high preset's cone of the light at `lamp` reaches felt point `q`.
bool inCone(glm::dvec3 q, glm::dvec3 lamp) {
  const double reach = glm::length(glm::dvec2(q - lamp));
  return std::atan2(reach, lamp.z - q.z) < glm::radians(double(render::kHighSpotOuterDeg));
}

/// The light of the lamp at `lamp` on felt point `q`, but for its strength: its spot cone (full
/// inside the high preset's inner angle, none beyond the outer, smoothstep between), the inverse
/// square and the cosine of incidence.
double lampLightOn(glm::dvec3 q, glm::dvec3 lamp) {
  const glm::dvec3 to = lamp - q;
  const double d2 = glm::dot(to, to);
  const double c = to.z / std::sqrt(d2);
  const double inner = std::cos(glm::radians(double(render::kHighSpotInnerDeg)));
  const double outer = std::cos(glm::radians(double(render::kHighSpotOuterDeg)));
  const double t = std::clamp((c - outer) / (inner - outer), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t) * c / d2;
}

/// Whether felt point `q` sees the light at `lamp` past every ball (radius r).
bool litBy(glm::dvec3 q, glm::dvec3 lamp, const std::vector<glm::dvec3>& balls, double r) {
  for (const glm::dvec3& b : balls) {
    if (segmentDistance(q, lamp, b) < 1.02 * r) return false;
  }
  return true;
}

std::string ballsFlag(const std::vector<std::pair<int, glm::dvec2>>& balls) {
  std::string flag = "--balls";
  for (const auto& [id, at] : balls) {
    flag += " " + std::to_string(id) + " " + std::to_string(at.x) + " " + std::to_string(at.y);
  }
  return flag;
}

// Two balls round the foot of each lamp, 0.5-0.6 m out, inside its cone. For each lamp whose
// light reaches a ball (and gives the most of the light beyond it), the felt on the far side of
// the ball from that lamp, inside the shadow the test works out (the felt from which the ball
// hides the light), is darker than the felt on either side across that line, which every lamp
// reaching it lights.
TEST_F(HighPresetTest, EachLampsShadowOfABallFallsAwayFromThatLamp) {
  const auto spec = nineFootSpec();
  const double r = spec.params.ball_radius;
  const auto lights = lightsOver(spec);
  const std::vector<std::pair<int, glm::dvec2>> laid{{2, glm::dvec2(lights[0].x + 0.5, 0.1)},
                                                     {4, glm::dvec2(lights[1].x, 0.55)},
                                                     {6, glm::dvec2(lights[0].x - 0.5, -0.3)},
                                                     {8, glm::dvec2(lights[1].x + 0.45, -0.35)}};
  const Image image =
      view("--quality high --scene top --cue-at 0.0 -0.55 " + ballsFlag(laid) + " --frames 1");
  ASSERT_EQ(image.width, camera_.width);
  std::vector<glm::dvec3> centres{glm::dvec3(0.0, -0.55, r)};
  for (const auto& [id, at] : laid) centres.emplace_back(at, r);
  int checked = 0;
  for (std::size_t b = 1; b < centres.size(); ++b) {
    const glm::dvec3 c = centres[b];
    for (const glm::dvec3& lamp : lights) {
      const glm::dvec2 foot(lamp.x, lamp.y);
      const double reach = glm::length(glm::dvec2(c) - foot);
      // Inside the high preset's cone, with room for the shadow past the ball's outline.
      if (std::atan2(reach, lamp.z) > glm::radians(render::kHighSpotOuterDeg - 4.0)) continue;
      const glm::dvec2 away = glm::normalize(glm::dvec2(c) - foot);
      const glm::dvec2 across(-away.y, away.x);
      // The shadow's far edge along `away`: the farthest felt point the ball hides the lamp from.
      double edge = r;
      while (!litBy(glm::dvec3(glm::dvec2(c) + (edge + 0.001) * away, 0.0), lamp, {c}, r)) {
        edge += 0.001;
      }
      if (edge < 1.4 * r) continue;
      const double s = 0.5 * (1.15 * r + edge);  // between the ball's outline and the edge
      const glm::dvec3 far(glm::dvec2(c) + s * away, 0.0);
      ASSERT_FALSE(litBy(far, lamp, centres, r));
      // Where this lamp gives under two thirds of the lamps' light, its shadow is the other's
      // business.
      if (lampLightOn(far, lamp) <
          2.0 * lampLightOn(far, lights[0] == lamp ? lights[1] : lights[0]))
        continue;
      double side = 0;
      for (const double sign : {-1.0, 1.0}) {
        const glm::dvec3 q(glm::dvec2(c) + sign * s * across, 0.0);
        for (const glm::dvec3& other : lights) {
          ASSERT_TRUE(!inCone(q, other) || litBy(q, other, centres, r))
              << "ball " << laid[b - 1].first
              << ": every lamp reaching the felt beside it lights it";
        }
        side += 0.5 * meanLuminance(image, camera_, q);
      }
      const double shadowed = meanLuminance(image, camera_, far);
      EXPECT_LT(shadowed, 0.85 * side)
          << "ball " << laid[b - 1].first << ", lamp at x " << lamp.x << ": " << shadowed
          << " beyond it, " << side << " beside it (" << s / r << " R out)";
      ++checked;
    }
  }
  EXPECT_GE(checked, 4) << "shadows checked";
}

/// The point of a sphere (centre c, radius r) that mirrors `light` to `eye`: its normal halves
/// the angle between the directions to the eye and to the light (fixed-point iteration from the
/// centre's directions; it converges as the ball is small beside both distances).
glm::dvec3 mirrorPoint(glm::dvec3 c, double r, glm::dvec3 eye, glm::dvec3 light) {
  glm::dvec3 n = glm::normalize(glm::normalize(eye - c) + glm::normalize(light - c));
  for (int i = 0; i < 30; ++i) {
    const glm::dvec3 p = c + r * n;
    n = glm::normalize(glm::normalize(eye - p) + glm::normalize(light - p));
  }
  return c + r * n;
}

// The 8 (black: any light on it is reflected) in the aiming view, between the lamps: the
// brightest pixel within 2 px of where the test puts each lamp's reflection is a bright spot, far
// brighter than the ball's body.
TEST_F(HighPresetTest, EachLampIsMirroredOnABallWhereTheCameraAndTheLampPutIt) {
  const auto spec = nineFootSpec();
  const double r = spec.params.ball_radius;
  const glm::dvec3 eight(-0.25, 0.02, r);
  // The cue aimed well away from the 8: no ghost ball drawn over it.
  const Image image = view(
      "--quality high --scene aim --cue-at -0.75 0.0 --balls 8 -0.25 0.02 "
      "--aim 35 --frames 1");
  ASSERT_EQ(image.width, camera_.width);
  const glm::vec3 centre_px = camera_.pixel(glm::vec3(eight));
  const glm::vec3 rim_px = camera_.pixel(glm::vec3(eight) + float(r) * camera_.right());
  const double radius_px = glm::length(glm::vec2(rim_px - centre_px));
  ASSERT_GT(radius_px, 12.0) << "the 8 is large enough in the view to find a spot on";
  // The ball's own pixels, well inside its outline.
  std::vector<double> body;
  for (int y = int(centre_px.y - radius_px); y <= int(centre_px.y + radius_px); ++y) {
    for (int x = int(centre_px.x - radius_px); x <= int(centre_px.x + radius_px); ++x) {
      if (std::hypot(double(x) - centre_px.x, double(y) - centre_px.y) < 0.8 * radius_px) {
        body.push_back(luminance(image.at(x, y)));
      }
    }
  }
  std::nth_element(body.begin(), body.begin() + body.size() / 2, body.end());
  const double median = body[body.size() / 2];
  EXPECT_LT(median, 70.0) << "the 8 is black";
  for (const glm::dvec3& lamp : lightsOver(spec)) {
    const glm::dvec3 spot = mirrorPoint(eight, r, glm::dvec3(camera_.eye), lamp);
    const glm::vec3 px = camera_.pixel(glm::vec3(spot));
    ASSERT_LT(glm::length(glm::vec2(px - centre_px)), radius_px) << "the spot lies on the ball";
    double brightest = 0;
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        brightest = std::max(brightest, luminance(image.at(int(px.x) + dx, int(px.y) + dy)));
      }
    }
    EXPECT_GT(brightest, 180.0) << "lamp at x " << lamp.x << ": pixel " << px.x << ", " << px.y;
    EXPECT_GT(brightest, 3.0 * median + 60.0) << "lamp at x " << lamp.x;
  }
}

/// Around each ball's outline (its projected radius ± 2 px), the share of pixels that are neither
/// the ball's flat colour nor the felt's (each read at the ball's centre and 2 R out): blends.
double blendedShare(const Image& image, const ReportedCamera& cam,
                    const std::vector<glm::dvec3>& balls, double r) {
  int blended = 0, total = 0;
  for (const glm::dvec3& c : balls) {
    const glm::vec3 centre = cam.pixel(glm::vec3(c));
    const double radius =
        glm::length(glm::vec2(cam.pixel(glm::vec3(c) + float(r) * cam.right()) - centre));
    const Rgb ball = image.at(int(centre.x), int(centre.y));
    const glm::vec3 out = cam.pixel(glm::vec3(c + glm::dvec3(0.0, 2.0 * r, 0.0)));
    const Rgb felt = image.at(int(out.x), int(out.y));
    const auto distance = [](const Rgb& a, const Rgb& b) {
      return std::sqrt(std::pow(a[0] - b[0], 2) + std::pow(a[1] - b[1], 2) +
                       std::pow(a[2] - b[2], 2));
    };
    const double apart = distance(ball, felt);
    EXPECT_GT(apart, 60.0) << "the ball stands out from the felt";
    for (int y = int(centre.y - radius - 3); y <= int(centre.y + radius + 3); ++y) {
      for (int x = int(centre.x - radius - 3); x <= int(centre.x + radius + 3); ++x) {
        if (std::abs(std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y) - radius) > 2.0) continue;
        const Rgb& p = image.at(x, y);
        ++total;
        if (distance(p, ball) > 0.15 * apart && distance(p, felt) > 0.15 * apart) ++blended;
      }
    }
  }
  return total > 0 ? double(blended) / total : 0.0;
}

// Unlit and untextured (flat colours), seen from above: in the high preset the pixels along each
// ball's outline blend ball and felt; in the full preset (one sample a pixel) none do.
TEST_F(HighPresetTest, TheBallsOutlinesAreAntiAliased) {
  const auto spec = nineFootSpec();
  const double r = spec.params.ball_radius;
  const std::vector<std::pair<int, glm::dvec2>> laid{{1, glm::dvec2(-0.4, 0.2)},
                                                     {2, glm::dvec2(0.3, -0.25)},
                                                     {3, glm::dvec2(0.8, 0.3)},
                                                     {8, glm::dvec2(-0.9, -0.3)}};
  std::vector<glm::dvec3> centres;
  for (const auto& [id, at] : laid) centres.emplace_back(at, r);
  const std::string flags =
      "--scene top --no-lighting --no-textures --cue-at 0.0 0.0 " + ballsFlag(laid);
  const Image high = view("--quality high --frames 1 " + flags);
  ASSERT_EQ(high.width, camera_.width);
  const double high_share = blendedShare(high, camera_, centres, r);
  const Image full = view("--quality full --frames 1 " + flags);
  ASSERT_EQ(full.width, camera_.width);
  const double full_share = blendedShare(full, camera_, centres, r);
  EXPECT_GT(high_share, 0.15) << "high preset: blended outline pixels";
  EXPECT_LT(full_share, 0.03) << "full preset: blended outline pixels";
}

// Seen from above, on lines across the table clear of the balls: the felt under each lamp at
// least 1.5 times as bright as midway between them.
TEST_F(HighPresetTest, TheFeltUnderEachLampIsHalfAgainAsBrightAsMidwayBetweenThem) {
  const auto spec = nineFootSpec();
  const Image image = view("--quality high --scene top --frames 1");
  ASSERT_EQ(image.width, camera_.width);
  for (const double y : {-0.15, 0.15}) {
    const double middle = meanLuminance(image, camera_, {0.0, y, 0.0}, 2);
    for (const glm::dvec3& lamp : lightsOver(spec)) {
      const double pool = meanLuminance(image, camera_, {lamp.x, y, 0.0}, 2);
      EXPECT_GE(pool, 1.5 * middle) << "y " << y << ", lamp at x " << lamp.x << ": " << pool
                                    << " under it, " << middle << " midway";
    }
  }
}

}  // namespace
}  // namespace pool::client::test
