// The table's light and sights in real frames: a pool of light on the felt under each lamp with
// darker felt between, the balls' shadows falling away from the nearest lamp, and the eighteen
// diamonds on the rails. Positions come from the table spec and the lamps' placement; the
// sidecar's camera projects them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "client/render/lamps.h"
#include "client/render/screenshot.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/screenshot_fixture.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

using LightTest = ScreenshotInfoTest;

table::TableSpec nineFoot() {
  auto spec = table::loadTableSpec("wpa-9ft");
  EXPECT_TRUE(static_cast<bool>(spec));
  return *spec;
}

/// The lamps hang over the table's long axis, a quarter of the length from each end.
std::array<double, 2> lampXs(const table::TableSpec& spec) {
  return {-spec.length / 4, spec.length / 4};
}

/// Mean luminance of the 5 × 5 pixels around table point `p` on the felt.
double feltLuminance(const Image& image, const ReportedCamera& cam, glm::vec3 p) {
  const glm::vec3 px = cam.pixel(p);
  double sum = 0;
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) sum += luminance(image.at(int(px.x) + dx, int(px.y) + dy));
  }
  return sum / 25.0;
}

/// Along the line y = `y` on the felt: a maximum within 0.12 m of under each lamp, clearly above
/// the felt midway between them and toward the ends.
void expectPoolUnderEachLamp(const Image& image, const ReportedCamera& cam,
                             const table::TableSpec& spec, double y) {
  const auto lamps = lampXs(spec);
  const double half = spec.length / 2 - 0.12;
  std::vector<std::pair<double, double>> profile;  // x, luminance
  for (double x = -half; x <= half; x += 0.02) {
    const glm::vec3 px = cam.pixel(glm::vec3(float(x), float(y), 0.0f));
    ASSERT_TRUE(cam.inside(px, 3.0f)) << "x " << x;
    profile.emplace_back(x, feltLuminance(image, cam, glm::vec3(float(x), float(y), 0.0f)));
  }
  const auto at = [&](double x) {
    double best = 1e9, lum = 0;
    for (const auto& [px, l] : profile) {
      if (std::abs(px - x) < best) best = std::abs(px - x), lum = l;
    }
    return lum;
  };
  const double middle = at(0.0);
  for (const double lamp : lamps) {
    // The brightest felt on this lamp's half of the table.
    double peak_x = 0, peak = -1;
    for (const auto& [x, l] : profile) {
      if (x * lamp > 0 && l > peak) peak = l, peak_x = x;
    }
    EXPECT_NEAR(peak_x, lamp, 0.12) << "the pool's brightest felt lies under the lamp";
    EXPECT_GT(peak, middle * 1.2) << "darker felt between the lamps (y " << y << ")";
    EXPECT_GT(peak, at(lamp > 0 ? half : -half) * 1.2) << "darker felt toward the end";
  }
}

TEST_F(LightTest, FeltIsBrightestUnderEachLampSeenFromAbove) {
  const Image image = view("--scene top");
  ASSERT_EQ(image.width, camera_.width);
  // Clear of the spread balls and their shadows.
  expectPoolUnderEachLamp(image, camera_, nineFoot(), -0.15);
  expectPoolUnderEachLamp(image, camera_, nineFoot(), 0.5);
}

TEST_F(LightTest, FeltIsBrightestUnderEachLampInTheOverview) {
  const Image image = view("--scene rack");
  ASSERT_EQ(image.width, camera_.width);
  expectPoolUnderEachLamp(image, camera_, nineFoot(), 0.35);  // beside the rack
}

TEST_F(LightTest, BallShadowsFallAwayFromTheNearestLamp) {
  const Image image = view("--scene top");
  ASSERT_EQ(image.width, camera_.width);
  auto scene = render::spreadScene();
  ASSERT_TRUE(static_cast<bool>(scene));
  const auto spec = nineFoot();
  const double r = spec.params.ball_radius;
  int checked = 0;
  for (const auto& ball : scene->balls) {
    const glm::dvec2 at(ball.pos.x(), ball.pos.y());
    const auto lamps = lampXs(spec);
    const double d0 = glm::length(at - glm::dvec2(lamps[0], 0.0));
    const double d1 = glm::length(at - glm::dvec2(lamps[1], 0.0));
    if (std::abs(d0 - d1) < 0.2) continue;  // about as near to both: shadows both ways
    if (spec.width / 2 - std::abs(at.y) < 2 * r) continue;  // on the cushion: the next test's
    const glm::dvec2 lamp(d0 < d1 ? lamps[0] : lamps[1], 0.0);
    const glm::dvec2 away = glm::normalize(at - lamp);
    // Just outside the ball's outline as the camera sees it, the same distance out on the far and
    // the near side: the first distance from 1.3 R where the eye's ray to the felt misses the ball.
    const glm::dvec3 centre(ball.pos.x(), ball.pos.y(), ball.pos.z());
    const auto seen = [&](double s) {
      for (const double sign : {1.0, -1.0}) {
        const glm::dvec3 q(at + sign * s * away, 0.0);
        const glm::dvec3 ray = glm::normalize(q - glm::dvec3(camera_.eye));
        const glm::dvec3 to_c = centre - glm::dvec3(camera_.eye);
        const double miss = glm::length(to_c - ray * glm::dot(to_c, ray));
        if (miss < 1.15 * r) return false;
      }
      return true;
    };
    double s = 1.3 * r;
    while (!seen(s)) s += 0.05 * r;
    const auto felt = [&](double sign) {
      const glm::dvec2 p = at + sign * s * away;
      return feltLuminance(image, camera_, glm::vec3(float(p.x), float(p.y), 0.0f));
    };
    const double far = felt(1.0), near = felt(-1.0);
    EXPECT_LT(far, near * 0.85) << "ball " << ball.id << " at " << s / r << " R: far side " << far
                                << ", near " << near;
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

// The ball against the +y cushion near the head lamp darkens the cushion beside it, on its side
// away from the lamp: darker there than on its side toward the lamp and than the same cushion
// 10 cm farther along.
TEST_F(LightTest, ABallAgainstACushionDarkensTheCushionAwayFromTheLamp) {
  const Image image = view("--scene top");
  auto scene = render::spreadScene();
  ASSERT_TRUE(static_cast<bool>(scene));
  const auto spec = nineFoot();
  const double r = spec.params.ball_radius;
  const render::SceneBall* ball = nullptr;
  for (const auto& b : scene->balls) {
    if (spec.width / 2 - b.pos.y() < 1.5 * r) ball = &b;
  }
  ASSERT_NE(ball, nullptr) << "the top scene has a ball against the +y cushion";
  const auto lamps = lampXs(spec);
  const double lamp =
      std::abs(lamps[0] - ball->pos.x()) < std::abs(lamps[1] - ball->pos.x()) ? lamps[0] : lamps[1];
  const double away = ball->pos.x() > lamp ? 1.0 : -1.0;
  // The cushion's top just past the nose (a quarter radius on), at the cushion's height.
  const float y = float(spec.width / 2 + 0.25 * r);
  const float z = float(spec.params.cushion_height);
  const auto cushion = [&](double x) {
    const glm::vec3 px = camera_.pixel(glm::vec3(float(x), y, z));
    EXPECT_TRUE(camera_.inside(px, 3.0f));
    double sum = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) sum += luminance(image.at(int(px.x) + dx, int(px.y) + dy));
    }
    return sum / 9.0;
  };
  const double x = ball->pos.x();
  const double shaded = cushion(x + away * r), toward = cushion(x - away * 1.8 * r);
  const double beyond = cushion(x + away * 0.1);
  EXPECT_LT(shaded, 0.85 * beyond) << "beside the ball " << shaded << ", 10 cm on " << beyond;
  EXPECT_LT(shaded, toward) << "away from the lamp " << shaded << ", toward it " << toward;
}

/// Mother-of-pearl: bright and nearly grey.
bool isPearl(const Rgb& p) {
  return std::min({p[0], p[1], p[2]}) > 140 &&
         std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) < 70;
}

/// The 18 diamonds on the rail tops: six on each long rail at the eighths of the length (not
/// 0, 4, 8: the pockets), three on each end rail at the quarters of the width, across the middle
/// of the wooden rail, which begins cushion_width behind the nose line.
std::vector<glm::vec3> diamonds(const table::TableSpec& spec) {
  const double top = spec.params.cushion_height + 0.005;  // the rail top over the nose
  const double mid = spec.cushion_width + spec.rail_width / 2;
  std::vector<glm::vec3> out;
  for (const double side : {-1.0, 1.0}) {
    for (const int k : {1, 2, 3, 5, 6, 7}) {
      out.emplace_back(float(-spec.length / 2 + spec.length * k / 8),
                       float(side * (spec.width / 2 + mid)), float(top));
    }
  }
  for (const double end : {-1.0, 1.0}) {
    for (const int k : {1, 2, 3}) {
      out.emplace_back(float(end * (spec.length / 2 + mid)),
                       float(-spec.width / 2 + spec.width * k / 4), float(top));
    }
  }
  return out;
}

/// Whether a lamp shade drawn in the view (its opacity in the sidecar over zero) stands between
/// the eye and `p`: the line of sight passes through the sphere holding the shade.
bool behindAShade(const nlohmann::json& info, const ReportedCamera& cam, glm::vec3 p) {
  for (const auto& lamp : info.at("lamps")) {
    if (lamp.at("opacity").get<double>() <= 0.0) continue;
    const auto& at = lamp.at("light").at("pos");
    const glm::vec3 shade(at[0].get<float>(), at[1].get<float>(),
                          at[2].get<float>() + 0.05f);  // about the shade's middle
    const glm::vec3 sight = glm::normalize(p - cam.eye);
    const float along = glm::dot(shade - cam.eye, sight);
    if (along <= 0.0f || along >= glm::length(p - cam.eye)) continue;
    if (glm::length(cam.eye + along * sight - shade) < render::kShadeBound) return true;
  }
  return false;
}

/// The diamonds, but those a lamp shade in view hides (at most `hidden_at_most` of them).
void expectDiamonds(const Image& image, const ReportedCamera& cam, const table::TableSpec& spec,
                    const nlohmann::json& info, int hidden_at_most = 0) {
  const auto all = diamonds(spec);
  ASSERT_EQ(all.size(), 18u);
  int found = 0, hidden = 0;
  for (const glm::vec3& d : all) {
    const glm::vec3 px = cam.pixel(d);
    ASSERT_TRUE(cam.inside(px));
    if (behindAShade(info, cam, d)) {
      ++hidden;
      continue;
    }
    if (countInDisc(image, px.x, px.y, 2.5, isPearl) >= 2) ++found;
    // A sixteenth of the length (or width) along the rail: bare wood.
    const bool end_rail = std::abs(d.x) > spec.length / 2;
    const glm::vec3 step = end_rail ? glm::vec3(0, float(spec.width / 8), 0)
                                    : glm::vec3(float(spec.length / 16), 0, 0);
    const glm::vec3 between = cam.pixel(d + step);
    EXPECT_EQ(countInDisc(image, between.x, between.y, 2.5, isPearl), 0)
        << "wood between the diamonds at (" << d.x << ", " << d.y << ")";
  }
  EXPECT_LE(hidden, hidden_at_most);
  EXPECT_EQ(found, 18 - hidden);
}

TEST_F(LightTest, EighteenDiamondsOnTheRailsSeenFromAbove) {
  const Image image = view("--scene top");
  ASSERT_EQ(image.width, camera_.width);
  expectDiamonds(image, camera_, nineFoot(), readInfo(info()));
}

TEST_F(LightTest, EighteenDiamondsOnTheRailsInTheOverview) {
  const Image image = view("--scene rack");
  ASSERT_EQ(image.width, camera_.width);
  // The lamps hang between the eye and the far rail: each may stand before two diamonds.
  expectDiamonds(image, camera_, nineFoot(), readInfo(info()), 4);
}

glm::vec3 posOf(const nlohmann::json& point) {
  const auto& p = point.at("pos");
  return {p[0], p[1], p[2]};
}

/// Oxblood enamel, lit or in shade: red well above green and blue.
bool isShade(const Rgb& p) {
  return p[0] > 25 && p[0] > 1.8 * p[1] && p[0] > 1.8 * p[2];
}

// The overview hangs both shades over the table (each lamp's pixel is enamel, its opacity 1);
// a ball laid where the head lamp's shade stands between it and the eye (on the line from the
// eye through the shade's rim, the test's own) fades that shade alone, and the ball shows.
TEST_F(LightTest, TheShadesHangInTheOverviewAndFadeOnlyBeforeABall) {
  const Image image = view("--scene rack");
  ASSERT_EQ(image.width, camera_.width);
  const nlohmann::json info = readInfo(this->info());
  for (const auto& lamp : info.at("lamps")) {
    EXPECT_EQ(lamp.at("opacity").get<double>(), 1.0);
    const auto& px = lamp.at("light").at("px");
    EXPECT_GE(countInDisc(image, px[0].get<double>(), px[1].get<double>(), 3.0, isShade), 20)
        << "a shade at " << lamp.at("light").dump();
  }
  const auto spec = nineFoot();
  const double r = spec.params.ball_radius;
  // The head lamp's shade's rim on the eye's side, 1 cm in: what lies on the line from the eye
  // through it is hidden.
  const glm::vec3 eye = camera_.eye;
  const float toward = eye.y < 0.0f ? -1.0f : 1.0f;
  const glm::vec3 rim(float(-spec.length / 4), toward * (render::kShadeRadius - 0.01f),
                      render::kLampHeight - render::kShadeRimBelow);
  const float t = (eye.z - float(r)) / (eye.z - rim.z);
  const glm::vec3 hidden = eye + t * (rim - eye);
  ASSERT_LT(std::abs(hidden.y), spec.width / 2 - r) << "the hidden place is on the bed";
  const Image faded =
      view("--scene rack --balls 2 " + std::to_string(hidden.x) + " " + std::to_string(hidden.y));
  const nlohmann::json after = readInfo(this->info());
  EXPECT_EQ(after.at("lamps")[0].at("opacity").get<double>(), 0.0) << "the head lamp's shade";
  EXPECT_EQ(after.at("lamps")[1].at("opacity").get<double>(), 1.0) << "the foot lamp's shade";
  const glm::vec3 ball = camera_.pixel(glm::vec3(hidden.x, hidden.y, float(r)));
  const auto blue = [](const Rgb& p) { return p[2] > p[0] + 30 && p[2] > p[1] + 30; };
  EXPECT_GE(countInDisc(faded, ball.x, ball.y, 6.0, blue), 30) << "the 2 is seen";
}

TEST_F(LightTest, TheCueCastsAShadowOnTheFeltAwayFromTheLamp) {
  // The cue beside the head lamp (which hangs over y = 0), aimed up the table, seen from above
  // and behind: its shadow falls on the felt on its side away from the lamp.
  const Image image =
      view("--scene aim --cue-at -0.6 0.35 --aim 10 --camera-elevation 55 --camera-distance 1.1");
  const auto info = readInfo(this->info());
  ASSERT_TRUE(info.contains("cue"));
  const glm::vec3 tip = posOf(info.at("cue").at("tip"));
  const glm::vec3 butt = posOf(info.at("cue").at("butt"));
  glm::vec3 lamp = posOf(info.at("lamps")[0].at("light"));
  for (const auto& l : info.at("lamps")) {
    if (glm::length(posOf(l.at("light")) - tip) < glm::length(lamp - tip)) {
      lamp = posOf(l.at("light"));
    }
  }
  double shadowed = 0, beside = 0;
  int samples = 0;
  for (float s = 0.1f; s <= 0.28f; s += 0.01f) {
    const glm::vec3 p = tip + (butt - tip) * (s / glm::length(butt - tip));
    // The ray from the lamp through the cue's axis meets the slate here...
    const glm::vec3 shadow = lamp + (p - lamp) * (lamp.z / (lamp.z - p.z));
    // ...and the felt as far on the other side of the cue (toward the lamp) is lit.
    const glm::vec3 under(p.x, p.y, 0.0f);
    const glm::vec3 lit = under + (under - shadow);
    const glm::vec3 a = camera_.pixel(shadow), b = camera_.pixel(lit);
    ASSERT_TRUE(camera_.inside(a) && camera_.inside(b)) << "at " << s;
    shadowed += luminance(image.at(int(a.x), int(a.y)));
    beside += luminance(image.at(int(b.x), int(b.y)));
    ++samples;
  }
  EXPECT_LT(shadowed / samples + 8.0, beside / samples)
      << "shadow " << shadowed / samples << ", lit felt " << beside / samples;
}

}  // namespace
}  // namespace pool::client::test
