// pool-client --screenshot --scene aim: the aiming view of the racked table. The tests work out
// where things must be from the table spec, the rack and the physics' strike frame, project them
// through the camera the sidecar reports, and look at the pixels there: the cue's wood along the
// struck line, the cue drawn back with the power, the ghost ball's outline at the first contact,
// the lamps never filling the view, and the far lamp hanging over the shot in the HUD's aiming
// view.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "client/render/cue_pose.h"
#include "client/render/lamps.h"
#include "client/render/palette.h"
#include "client/render/scene.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/screenshot_fixture.h"
#include "table/rack.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

class AimViewTest : public ScreenshotInfoTest {
 protected:
  /// Renders the aim scene with `flags` and reads its sidecar.
  Image aimView(const std::string& flags) { return view("--scene aim " + flags); }
};

struct Table {
  table::TableSpec spec;
  double radius = 0.0;
  glm::vec3 cue_ball{0.0f};  ///< on the head spot
  Eigen::Vector2d apex;      ///< the foot spot
};

Table nineFoot() {
  auto spec = table::loadTableSpec("wpa-9ft");
  EXPECT_TRUE(static_cast<bool>(spec));
  Table t{*spec, spec->params.ball_radius, {}, {}};
  const auto spots = table::spotsFor(t.spec);
  t.cue_ball = {float(spots.head_spot.x()), float(spots.head_spot.y()), float(t.radius)};
  t.apex = spots.foot_spot;
  return t;
}

/// The cue's direction toward the ball and the struck point, as common/physics/cue_strike.cpp
/// defines them: d = (cos θ cos ψ, cos θ sin ψ, −sin θ), right = (sin ψ, −cos ψ, 0),
/// up = right × d, contact = R (a right + b up − √(1 − a² − b²) d).
struct StrikeLine {
  glm::dvec3 d, point;
};

StrikeLine strikeLine(const Table& t, double yaw, double elevation, double a, double b) {
  const glm::dvec3 d(std::cos(elevation) * std::cos(yaw), std::cos(elevation) * std::sin(yaw),
                     -std::sin(elevation));
  const glm::dvec3 right(std::sin(yaw), -std::cos(yaw), 0.0);
  const glm::dvec3 up = glm::cross(right, d);
  const glm::dvec3 centre(t.cue_ball);
  return {d, centre + t.radius * (a * right + b * up - std::sqrt(1.0 - a * a - b * b) * d)};
}

/// Maple: a warm light wood, red over green over blue.
bool isMaple(const Rgb& p) {
  return p[0] > 90 && p[0] > p[1] && p[1] > p[2] && p[0] - p[2] > 45;
}

/// Share of the points `s` metres back from `from` along −d (those inside the image) that show
/// maple within a pixel.
double mapleShare(const Image& image, const ReportedCamera& cam, glm::dvec3 from, glm::dvec3 d,
                  double s0, double s1, glm::dvec3 shift = glm::dvec3(0.0), int* seen = nullptr) {
  int inside = 0, wood = 0;
  for (double s = s0; s <= s1; s += 0.01) {
    const glm::vec3 px = cam.pixel(glm::vec3(from - d * s + shift));
    if (!cam.inside(px)) continue;
    ++inside;
    if (countInDisc(image, px.x, px.y, 1.5, isMaple) > 0) ++wood;
  }
  if (seen) *seen = inside;
  return inside ? double(wood) / inside : 0.0;
}

TEST_F(AimViewTest, CueWoodRunsAlongTheStruckLineAndNotBesideIt) {
  const Table t = nineFoot();
  const double yaw = 2.0 * kDeg, elevation = 5.0 * kDeg, a = 0.3, b = -0.2;
  const Image image = aimView("--aim 2 --elevation 5 --tip-side 0.3 --tip-height -0.2");
  ASSERT_EQ(image.width, camera_.width);
  const StrikeLine line = strikeLine(t, yaw, elevation, a, b);
  int seen = 0;
  // The shaft from 4 cm behind the tip (past the ferrule) to where it leaves the image.
  EXPECT_GT(mapleShare(image, camera_, line.point, line.d, 0.04, 0.6, {}, &seen), 0.9);
  EXPECT_GE(seen, 10) << "the cue's line should cross much of the view";
  // Four shaft widths to either side (horizontally) is felt, not wood.
  const glm::dvec3 side = glm::normalize(glm::cross(line.d, glm::dvec3(0, 0, 1))) * 0.03;
  EXPECT_LT(mapleShare(image, camera_, line.point, line.d, 0.04, 0.6, side), 0.1);
  EXPECT_LT(mapleShare(image, camera_, line.point, line.d, 0.04, 0.6, -side), 0.1);
}

TEST_F(AimViewTest, PowerDrawsTheCueBackAlongItsLine) {
  const Table t = nineFoot();
  const StrikeLine line = strikeLine(t, 0.0, 0.0, 0.0, 0.0);
  const Image rest = aimView("--aim 0 --power 0");
  const ReportedCamera at_rest = camera_;
  const Image drawn = aimView("--aim 0 --power 1");
  const double back = render::kMaxDrawBack;
  // At rest the shaft starts right behind the ball; drawn back, that stretch is empty felt and
  // the cue begins kMaxDrawBack further back.
  EXPECT_GT(mapleShare(rest, at_rest, line.point, line.d, 0.04, back - 0.04), 0.9);
  EXPECT_LT(mapleShare(drawn, camera_, line.point, line.d, 0.04, back - 0.04), 0.2);
  EXPECT_GT(mapleShare(drawn, camera_, line.point, line.d, back + 0.04, back + 0.4), 0.9);
}

/// The cue ball's centre where, sent along `yaw` from `from`, it first touches a racked ball.
std::optional<glm::dvec2> firstContact(const Table& t, glm::dvec2 from, double yaw) {
  const glm::dvec2 dir(std::cos(yaw), std::sin(yaw));
  std::optional<double> nearest;
  for (const auto& b : table::rackBalls(table::RackType::EightBall, t.spec, t.radius, 0)) {
    const glm::dvec2 c(b.pos.x(), b.pos.y());
    const double along = glm::dot(c - from, dir);
    const double miss2 = glm::dot(c - from, c - from) - along * along;
    const double reach2 = 4.0 * t.radius * t.radius;
    if (along <= 0.0 || miss2 > reach2) continue;
    const double s = along - std::sqrt(reach2 - miss2);
    if (!nearest || s < *nearest) nearest = s;
  }
  if (!nearest) return std::nullopt;
  return from + dir * *nearest;
}

TEST_F(AimViewTest, GhostBallOutlineSitsAtTheFirstContact) {
  const Table t = nineFoot();
  const double yaw = 1.0 * kDeg;  // a thin cut on the apex ball
  const Image image = aimView("--aim 1");
  const auto contact = firstContact(t, glm::dvec2(t.cue_ball.x, t.cue_ball.y), yaw);
  ASSERT_TRUE(contact.has_value());
  const glm::vec3 centre(float(contact->x), float(contact->y), float(t.radius));
  // The silhouette circle across the line of sight, and a ring well outside it.
  const glm::vec3 sight = glm::normalize(centre - camera_.eye);
  const glm::vec3 right = glm::normalize(glm::cross(sight, glm::vec3(0, 0, 1)));
  const glm::vec3 up = glm::cross(right, sight);
  const auto bright = [](const Rgb& p) { return std::min({p[0], p[1], p[2]}) > 200.0; };
  int on = 0, off = 0;
  constexpr int kPoints = 24;
  for (int i = 0; i < kPoints; ++i) {
    const double ang = 2.0 * std::numbers::pi * i / kPoints;
    const glm::vec3 rim = float(std::cos(ang)) * right + float(std::sin(ang)) * up;
    const glm::vec3 edge = camera_.pixel(centre + float(t.radius) * rim);
    const glm::vec3 out = camera_.pixel(centre + float(t.radius * 1.6) * rim);
    ASSERT_TRUE(camera_.inside(edge));
    if (countInDisc(image, edge.x, edge.y, 1.5, bright) > 0) ++on;
    if (countInDisc(image, out.x, out.y, 0.8, bright) > 0) ++off;
  }
  EXPECT_GE(on, kPoints - 2) << "outline pixels on the ghost ball's silhouette";
  EXPECT_LE(off, 4) << "no outline well outside it";
}

/// Pixels of a lamp: its enamel shade (lit) or the glow inside it and the bulb.
bool isLamp(const Rgb& p) {
  const glm::vec3 c = render::shadeColour();
  const bool glow = p[0] > 200 && p[1] > 170 && p[2] > 100 && p[0] - p[2] > 40;
  return glow || shadeOf(p, {c.r, c.g, c.b});
}

TEST_F(AimViewTest, NoLampCoversMoreThanFivePercentOfTheAimingView) {
  const int total = 1280 * 720;
  for (const std::string flags :
       {"", "--camera-elevation 30", "--camera-elevation 60", "--camera-elevation 85",
        "--camera-elevation 20 --camera-distance 2", "--aim 180 --camera-elevation 45"}) {
    const Image image = aimView(flags);
    ASSERT_EQ(image.width, 1280) << flags;
    EXPECT_LT(count(image, isLamp), total / 20) << flags;
  }
}

TEST_F(AimViewTest, LampsAreSeenFromAfarUnderTheirHeight) {
  // The detector above finds a lamp where one is in view: far back and low, the foot lamp hangs
  // in the top of the picture, a quarter of the length from the foot cushion.
  const Table t = nineFoot();
  const Image image = aimView("--camera-distance 3 --camera-elevation 8");
  const glm::vec3 light(float(t.spec.length / 4), 0.0f, render::kLampHeight);
  const glm::vec3 px = camera_.pixel(light);
  ASSERT_TRUE(camera_.inside(px));
  EXPECT_GT(countInDisc(image, px.x, px.y, 30.0, isLamp), 300);
  EXPECT_LT(count(image, isLamp), 1280 * 720 / 20);
}

TEST_F(AimViewTest, TheFarShadeHangsOverTheTableInTheHudsAimingViewClearOfTheShot) {
  // The window's aiming view (the shot framed in the column the panes leave) of the break from
  // the head spot at the apex ball: it tilts up until the foot lamp, 0.95 m over the slate a
  // quarter of the length from the foot cushion, hangs inside the column under the top panes,
  // the cue ball, the apex ball and the pockets still in the column below it.
  const Table t = nineFoot();
  const Image image = aimView("--hud");
  ASSERT_EQ(image.width, 1280);
  const glm::vec3 light(float(t.spec.length / 4), 0.0f, render::kLampHeight);
  const glm::vec3 px = camera_.pixel(light);
  ASSERT_TRUE(camera_.inside(px)) << px.x << " " << px.y;
  EXPECT_GT(px.y, 42.0f) << "under the last shot's pane (10-42 px)";
  EXPECT_GT(countInDisc(image, px.x, px.y, 30.0, isLamp), 300);
  EXPECT_LT(count(image, isLamp), 1280 * 720 / 20);
  // No shade over the shot: the disc round the light that holds the whole shade (kShadeBound,
  // as drawn at its distance) clear of the cue ball and the apex ball (1.5 radii round their
  // centres as drawn) and of the mouths of the foot pockets the shot may head for.
  const auto drawnRadius = [&](glm::vec3 centre, float r) {
    return glm::length(glm::vec2(camera_.pixel(centre + r * camera_.up()) - camera_.pixel(centre)));
  };
  const float shade = drawnRadius(light, render::kShadeBound);
  const glm::vec3 apex(float(t.apex.x()), float(t.apex.y()), float(t.radius));
  for (const glm::vec3 p : {t.cue_ball, apex}) {
    const glm::vec3 at = camera_.pixel(p);
    const float r = drawnRadius(p, float(t.radius));
    ASSERT_TRUE(camera_.inside(at));
    EXPECT_LT(at.y, 720.0f - r) << "whole above the bottom edge";
    EXPECT_GT(glm::length(glm::vec2(at - px)), shade + 1.5f * r) << p.x;
  }
  const auto geometry = table::buildTableGeometry(t.spec);
  for (const auto& hole : geometry.holes) {
    if (hole.centre.x() < t.spec.length / 4) continue;  // the foot corners
    const glm::vec3 at =
        camera_.pixel(glm::vec3(float(hole.centre.x()), float(hole.centre.y()), float(t.radius)));
    ASSERT_TRUE(camera_.inside(at)) << hole.name;
    EXPECT_GT(glm::length(glm::vec2(at - px)), shade + 10.0f) << hole.name;
  }
  // The shade is above the shot: its light over the apex ball's pixel.
  EXPECT_LT(px.y, camera_.pixel(apex).y - 100.0f);
}

}  // namespace
}  // namespace pool::client::test
