// The aiming view frames the shot: the cue ball, the ghost ball, the object ball and its pocket
// drawn inside the part of the window the HUD's panes leave clear, for long shots, a cue ball
// frozen to a rail and a cut to a far pocket.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "client/app/camera_rig.h"
#include "client/app/clear_area.h"

namespace pool::app::test {
namespace {

constexpr double kR = 0.028575;
constexpr int kWidth = 1280, kHeight = 720;

/// The standing panes as the HUD lays them out at 1280 × 720 (HudPanes' layout with long texts:
/// Match, the last shot's banner, Shot, Match log), pixels from the top-left corner.
const std::vector<ScreenRect> kPanes{
    {10, 10, 350, 240}, {422, 10, 857, 78}, {10, 447, 350, 710}, {886, 10, 1270, 312}};

/// Pixel of `p` through `v`: the test's own projection (glm's lookAt with +z up, perspective).
glm::dvec2 pixelOf(const ViewPoint& v, const Eigen::Vector3d& p) {
  const auto g = [](const Eigen::Vector3d& q) { return glm::dvec3(q.x(), q.y(), q.z()); };
  const glm::dmat4 view = glm::lookAt(g(v.eye), g(v.target), glm::dvec3(0, 0, 1));
  const glm::dmat4 projection = glm::perspective(glm::radians(v.fov_y_deg),
                                                 static_cast<double>(kWidth) / kHeight, 0.05, 50.0);
  const glm::dvec4 c = projection * view * glm::dvec4(g(p), 1.0);
  if (c.w <= 0) return {-1e9, -1e9};
  return {(c.x / c.w * 0.5 + 0.5) * kWidth, (0.5 - c.y / c.w * 0.5) * kHeight};
}

/// A shot: the cue ball, the object ball, the pocket's mouth; the aim is the ghost ball's line
/// (the cue ball's centre to the point 2R behind the object ball on the pocket's line).
struct Layout {
  std::string name;
  Eigen::Vector2d cue, object, pocket;
  double eye_above = 0.0;  ///< rad the eye must stay above (a cue raised over a rail), 0: none
};

/// A shot's points as the controls hand them to the camera, and the view they get.
struct Framed {
  Eigen::Vector3d cue;
  std::vector<Eigen::Vector3d> ahead;  ///< the ghost ball, the object ball, the pocket
  ScreenRect area;
  ViewPoint view;
};

/// Frames `l` as the controls open a turn: behind the cue ball, raised over the ghost ball, the
/// shot framed, then the eye kept above a raised cue (the window does so each frame); `lights`
/// given to the camera first.
Framed frame(const Layout& l, const std::vector<Eigen::Vector3d>& lights = {}) {
  Framed f;
  const Eigen::Vector2d ghost = l.object - 2 * kR * (l.pocket - l.object).normalized();
  const double yaw = std::atan2(ghost.y() - l.cue.y(), ghost.x() - l.cue.x());
  f.cue = Eigen::Vector3d(l.cue.x(), l.cue.y(), kR);
  f.ahead = {{ghost.x(), ghost.y(), kR},
             {l.object.x(), l.object.y(), kR},
             {l.pocket.x(), l.pocket.y(), kR}};
  f.area = clearColumnFor(kWidth, kHeight, kPanes);
  CameraRig rig(2.54, 1.27, static_cast<double>(kWidth) / kHeight);
  rig.setLights(lights);
  rig.setAimArea(
      {f.area.x0 / kWidth, f.area.y0 / kHeight, f.area.x1 / kWidth, f.area.y1 / kHeight});
  rig.setAiming(true);
  rig.behindCue();
  rig.followCue(f.cue, yaw);
  rig.frameAim(f.cue, f.ahead.front(), kR);
  rig.frameShot(f.cue, f.ahead);
  if (l.eye_above > 0) rig.keepAimAbove(l.eye_above);
  rig.settle();
  f.view = rig.view();
  return f;
}

/// Every point of the shot drawn inside the column, the eye behind the cue ball.
void expectFramed(const Layout& l, const Framed& f) {
  const ViewPoint& v = f.view;
  EXPECT_LE((v.eye - f.cue).norm(), 3.0 + 1e-9) << "drawn back no further than 3 m";
  const std::vector<std::pair<const char*, Eigen::Vector3d>> shown{{"cue ball", f.cue},
                                                                   {"ghost ball", f.ahead[0]},
                                                                   {"object ball", f.ahead[1]},
                                                                   {"pocket", f.ahead[2]}};
  for (const auto& [what, p] : shown) {
    const glm::dvec2 px = pixelOf(v, p);
    EXPECT_GT(px.x, f.area.x0) << what;
    EXPECT_LT(px.x, f.area.x1) << what;
    EXPECT_GT(px.y, f.area.y0) << what;
    EXPECT_LT(px.y, f.area.y1) << what;
  }
  // Behind the cue ball, the cue's line toward the eye: the eye on the far side of the cue ball
  // from the shot, looking along it.
  const Eigen::Vector2d back = (v.eye - f.cue).head<2>();
  EXPECT_LT(back.dot(f.ahead[0].head<2>() - l.cue), 0.0);
}

class CameraAimFrameTest : public ::testing::TestWithParam<Layout> {};

TEST_P(CameraAimFrameTest, TheCueBallTheShotAndItsPocketAreDrawnClearOfThePanes) {
  const Framed f = frame(GetParam());
  // The column the panes leave: between the left panes and the match log, under the banner.
  ASSERT_EQ(f.area, (ScreenRect{350, 78, 886, 720}));
  expectFramed(GetParam(), f);
}

TEST_P(CameraAimFrameTest, ToldOfTheLampsTheViewHangsTheLampAheadInTheColumnAndStillFramesTheShot) {
  // The two lamps of a 9-ft table: 0.95 m over the slate, a quarter of the length from each end.
  const std::vector<Eigen::Vector3d> lamps{{-0.635, 0.0, 0.95}, {0.635, 0.0, 0.95}};
  const Layout& l = GetParam();
  const Framed plain = frame(l);
  const Framed f = frame(l, lamps);
  expectFramed(l, f);
  // The same eye, its look-at point raised: the view tilts up, never down.
  EXPECT_LT((f.view.eye - plain.view.eye).norm(), 1e-9);
  EXPECT_GE(f.view.target.z(), plain.view.target.z() - 1e-9);
  // Every layout but those with the cue raised over a rail (the eye 35° up, looking down on the
  // shot) plays up the table toward the foot lamp: its light is drawn in the column, below the
  // banner.
  if (l.eye_above > 0) return;
  const glm::dvec2 px = pixelOf(f.view, lamps[1]);
  EXPECT_GT(px.x, f.area.x0);
  EXPECT_LT(px.x, f.area.x1);
  EXPECT_GT(px.y, f.area.y0);
  EXPECT_LT(px.y, f.area.y1);
  // Which a view without the lamps does not show.
  EXPECT_LT(pixelOf(plain.view, lamps[1]).y, f.area.y0);
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, CameraAimFrameTest,
    ::testing::Values(
        // Corner to corner: from the head left corner's side to the foot right corner, 2.6 m.
        Layout{"CornerToCorner", {-1.1, -0.5}, {1.0, 0.45}, {1.27, 0.635}},
        // The length of the table straight up the middle into the foot's side of the rack spot.
        Layout{"FullLength", {-1.2, 0.0}, {1.1, 0.05}, {1.27, 0.10}},
        // Frozen to the long rail, along it to the corner: the cue raised over the rail (the eye
        // 10° above a 25° cue).
        Layout{
            "FrozenToTheLongRail", {-0.4, -0.635 + kR}, {0.9, -0.635 + kR}, {1.27, -0.635}, 0.61},
        // Frozen to the head rail, the length of the table to a ball by the foot right corner.
        Layout{"FrozenToTheShortRail", {-1.27 + kR, 0.2}, {1.1, 0.5}, {1.27, 0.635}, 0.61},
        // A cut of about 45 degrees to a far corner pocket.
        Layout{"CutToAFarPocket", {-0.9, 0.1}, {0.5, 0.35}, {1.27, -0.635}}),
    [](const ::testing::TestParamInfo<Layout>& layout) { return layout.param.name; });

}  // namespace
}  // namespace pool::app::test
