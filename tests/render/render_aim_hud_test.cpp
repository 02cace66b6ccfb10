// pool-client --screenshot --scene aim --hud: the aiming view as a player sees it at 1280 × 720,
// the window's HUD drawn over it. For long shots, a cue ball frozen to a rail and a cut to a far
// pocket, the cue ball, the object ball and the pocket are drawn inside the frame and under none
// of the panes the sidecar reports; the test works the shot out from the layout itself (the ghost
// ball's line to the pocket), checks the sidecar agrees, and that the cue is drawn along its line.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/screenshot_fixture.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

constexpr double kR = 0.028575;  // the 9-ft table's balls (checked against the spec below)

/// A shot: the cue ball, one object ball and the corner pocket it is aimed at (facing the foot
/// from the head, left is +y: the foot left corner is at (+L/2, +W/2)).
struct Layout {
  const char* name;
  double cue_x, cue_y;
  int ball;
  double ball_x, ball_y;
  const char* pocket;
  double pocket_x, pocket_y;  ///< the corner the ball is aimed at
};

class AimHudTest : public ScreenshotInfoTest, public ::testing::WithParamInterface<Layout> {};

TEST_P(AimHudTest, TheCueBallTheBallAndThePocketAreDrawnClearOfEveryPane) {
  const Layout& l = GetParam();
  const auto spec = table::loadTableSpec("wpa-9ft");
  ASSERT_TRUE(spec) << spec.error();
  ASSERT_DOUBLE_EQ(spec->params.ball_radius, kR);
  // The ghost ball: 2R behind the object ball on its line to the pocket; the cue aims at it.
  const Eigen::Vector2d cue(l.cue_x, l.cue_y), ball(l.ball_x, l.ball_y);
  const Eigen::Vector2d pocket(l.pocket_x, l.pocket_y);
  const Eigen::Vector2d ghost = ball - 2 * kR * (pocket - ball).normalized();
  const double yaw = std::atan2(ghost.y() - cue.y(), ghost.x() - cue.x());
  char flags[256];
  std::snprintf(flags, sizeof flags,
                "--scene aim --hud --cue-at %.6f %.6f --balls %d %.6f %.6f --aim %.6f", l.cue_x,
                l.cue_y, l.ball, l.ball_x, l.ball_y, yaw * 180.0 / std::numbers::pi);
  const Image image = view(flags);
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(camera_.mirrored(), "");
  const auto info = readInfo(this->info());

  // The sidecar's shot is the one the layout gives: this ball first, into this pocket.
  const auto& aim = info.at("aim");
  ASSERT_FALSE(aim.at("first_ball").is_null()) << "the cue's line misses the ball";
  EXPECT_EQ(aim.at("first_ball").get<int>(), l.ball);
  EXPECT_EQ(aim.value("pocket", ""), l.pocket);

  // The panes drawn: the four that stay up in play, at least.
  std::vector<std::array<double, 4>> panes;
  std::set<std::string> names;
  for (const auto& p : info.at("panes")) {
    names.insert(p.at("name").get<std::string>());
    panes.push_back({p.at("rect")[0], p.at("rect")[1], p.at("rect")[2], p.at("rect")[3]});
  }
  for (const char* pane : {"Match", "Last shot", "Shot", "Match log"}) {
    EXPECT_EQ(names.count(pane), 1u) << pane;
  }

  // Each point through the reported camera (the test's own projection): inside the image and
  // under no pane (a ball's radius of room), and where the sidecar says it is (0.5 px).
  const auto at = [](const Eigen::Vector2d& p) {
    return glm::vec3(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(kR));
  };
  const std::vector<std::pair<const char*, glm::vec3>> shown{
      {"cue ball", at(cue)}, {"object ball", at(ball)}, {"pocket", at(pocket)}};
  for (const auto& [what, p] : shown) {
    const glm::vec3 px = camera_.pixel(p);
    ASSERT_TRUE(camera_.inside(px, 4.0f)) << what << " at " << px.x << ", " << px.y;
    for (const auto& r : panes) {
      EXPECT_FALSE(px.x > r[0] - 4 && px.x < r[2] + 4 && px.y > r[1] - 4 && px.y < r[3] + 4)
          << what << " at " << px.x << ", " << px.y << " under a pane at " << r[0] << ", " << r[1]
          << " - " << r[2] << ", " << r[3];
    }
  }
  for (const auto& [key, p] : std::vector<std::pair<const char*, glm::vec3>>{
           {"cue_ball", at(cue)}, {"object_ball", at(ball)}}) {
    const glm::vec3 px = camera_.pixel(p);
    EXPECT_NEAR(aim.at(key).at("px")[0].get<double>(), px.x, 0.5) << key;
    EXPECT_NEAR(aim.at(key).at("px")[1].get<double>(), px.y, 0.5) << key;
  }

  // The cue drawn along its line: tip and butt in the vertical plane through the cue ball's
  // centre along the aim (1 mm), the butt behind the tip, the tip within a few cm of the ball.
  const auto& drawn = info.at("cue");
  const auto point = [](const nlohmann::json& j) {
    return Eigen::Vector3d(j.at("pos")[0], j.at("pos")[1], j.at("pos")[2]);
  };
  const Eigen::Vector3d tip = point(drawn.at("tip")), butt = point(drawn.at("butt"));
  const Eigen::Vector2d along(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d across(-along.y(), along.x());
  EXPECT_NEAR((tip.head<2>() - cue).dot(across), 0.0, 1e-3);
  EXPECT_NEAR((butt.head<2>() - cue).dot(across), 0.0, 1e-3);
  EXPECT_LT((butt.head<2>() - cue).dot(along), (tip.head<2>() - cue).dot(along));
  EXPECT_LT((tip.head<2>() - cue).norm(), kR + 0.05);
}

// A jump over a ball: the cue raised 30°, a ball 30 cm ahead on the line and the one to jump to
// beyond it. The first ball on the cue's line (the sidecar's, a table-plane prediction) is the one
// in the way; the cue ball, both balls and the cue's line are in the frame under no pane, and the
// cue is drawn at least as steep as aimed.
using AimHudJumpTest = ScreenshotInfoTest;

TEST_F(AimHudJumpTest, AJumpOverABallIsFramedWithTheCueRaised) {
  const Eigen::Vector2d cue(-0.8, 0.0), over(-0.5, 0.0), beyond(0.4, 0.0);
  const Image image =
      view("--scene aim --hud --cue-at -0.8 0 --balls 1 -0.5 0 2 0.4 0 --aim 0 --elevation 30");
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(camera_.mirrored(), "");
  const auto info = readInfo(this->info());
  ASSERT_FALSE(info.at("aim").at("first_ball").is_null());
  EXPECT_EQ(info.at("aim").at("first_ball").get<int>(), 1) << "the ball in the way first";
  EXPECT_GE(info.at("cue").at("drawn_elevation_deg").get<double>(), 30.0 - 1e-3);
  for (const auto& [what, p] : std::vector<std::pair<const char*, Eigen::Vector2d>>{
           {"cue ball", cue}, {"ball jumped", over}, {"ball beyond", beyond}}) {
    const glm::vec3 px = camera_.pixel(
        glm::vec3(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(kR)));
    ASSERT_TRUE(camera_.inside(px, 4.0f)) << what << " at " << px.x << ", " << px.y;
    for (const auto& pane : info.at("panes")) {
      const auto& r = pane.at("rect");
      EXPECT_FALSE(px.x > r[0].get<double>() - 4 && px.x < r[2].get<double>() + 4 &&
                   px.y > r[1].get<double>() - 4 && px.y < r[3].get<double>() + 4)
          << what << " under " << pane.at("name");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, AimHudTest,
    ::testing::Values(
        // Corner to corner: from by the head right corner to a ball by the foot left corner.
        Layout{"CornerToCorner", -1.1, -0.5, 3, 1.0, 0.45, "foot_left_corner", 1.27, 0.635},
        // The length of the table, nearly straight in.
        Layout{"FullLength", -1.2, 0.3, 5, 1.0, 0.55, "foot_left_corner", 1.27, 0.635},
        // Frozen to the long rail, along it to the corner (the cue raised over the rail).
        Layout{"FrozenToTheLongRail", -0.4, -0.635 + kR, 2, 0.9, -0.635 + kR + 0.002,
               "foot_right_corner", 1.27, -0.635},
        // Frozen to the head rail, the length of the table.
        Layout{"FrozenToTheShortRail", -1.27 + kR, 0.2, 4, 1.0, 0.5, "foot_left_corner", 1.27,
               0.635},
        // A cut of some 60 degrees to a far corner.
        Layout{"CutToAFarPocket", -0.9, 0.1, 6, 0.5, 0.35, "foot_right_corner", 1.27, -0.635}),
    [](const ::testing::TestParamInfo<Layout>& layout) { return std::string(layout.param.name); });

}  // namespace
}  // namespace pool::client::test
