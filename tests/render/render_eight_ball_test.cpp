// pool-client --screenshot --scene eightball: the giant 8-ball on its stool, the blue answer
// triangle in its dark window facing the viewer, and the answer's text on it.
#include <gtest/gtest.h>

#include "client/render/eight_ball_room.h"
#include "client/room/magic_eight_ball.h"
#include "support/screenshot_fixture.h"
#include "support/xvfb_run.h"

namespace pool::client::test {
namespace {

using RenderEightBallTest = ScreenshotInfoTest;

constexpr Rgb kTriangle{0.10, 0.22, 0.85};
constexpr Rgb kWood{0.34, 0.17, 0.07};

/// The window's centre and the ball's radius on screen, through the camera the sidecar reports
/// (checked no mirror: projected by the test's own ReportedCamera, not the renderer's code), and
/// the room's ball. The window is the point of the ball's surface nearest the viewer (it faces
/// them: the room's promise), found here from the reported eye and the ball alone.
struct RoomOnScreen {
  glm::vec3 window;
  glm::vec3 ball;
  double ball_radius;
};

RoomOnScreen project(const ReportedCamera& camera) {
  const glm::vec3 ball = render::EightBallRoom::ballCentre();
  const glm::vec3 side = glm::vec3(render::EightBallRoom::ballRadius(), 0, 0);
  const glm::vec3 c = camera.pixel(ball);
  const glm::vec3 e = camera.pixel(ball + side);
  const glm::vec3 toward_viewer = glm::normalize(camera.eye - ball);
  const glm::vec3 window = ball + toward_viewer * render::EightBallRoom::ballRadius();
  return {camera.pixel(window), c, glm::length(glm::vec2(e) - glm::vec2(c))};
}

TEST_F(RenderEightBallTest, TheBallOnItsStoolShowsTheAnswerTriangleWithText) {
  const Image image = view("--scene eightball --question \"Shall I break?\" --seed 3");
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(camera_.mirrored(), "");
  ASSERT_EQ(camera_.width, image.width);
  const RoomOnScreen room = project(camera_);
  ASSERT_TRUE(camera_.inside(room.window)) << "the window faces the viewer, in the image";
  ASSERT_GT(room.ball_radius, 100.0) << "a giant ball";
  const auto blue = [](const Rgb& p) { return shadeOf(p, kTriangle); };
  const double window = room.ball_radius * 0.4;
  EXPECT_GT(countInDisc(image, room.window.x, room.window.y, window, blue), 2000)
      << "the triangle in the window";
  // Letters: near-white, blended with the blue at their edges (red and green both high).
  const auto letter = [](const Rgb& p) { return p[0] > 150 && p[1] > 150; };
  EXPECT_GT(countInDisc(image, room.window.x, room.window.y, window, letter), 150)
      << "the answer's letters on the triangle";
  // The ball around the window is black (its rim beyond the window, below the triangle).
  EXPECT_GT(countInDisc(image, room.ball.x, room.ball.y + room.ball_radius * 0.8,
                        room.ball_radius * 0.15, isBlack),
            300);
  // The stool's wooden seat right under the ball.
  const auto wood = [](const Rgb& p) { return shadeOf(p, kWood); };
  EXPECT_GT(countInDisc(image, room.ball.x, room.ball.y + room.ball_radius * 1.15,
                        room.ball_radius * 0.3, wood),
            200);
}

TEST_F(RenderEightBallTest, ADifferentAnswerChangesTheTextOnly) {
  // Two seeds with different answers for the same question (found, not assumed).
  std::uint64_t other = 1;
  while (*room::answer("Shall I break?", other) == *room::answer("Shall I break?", 0)) ++other;
  const Image a = view("--scene eightball --question \"Shall I break?\" --seed 0");
  ASSERT_EQ(camera_.mirrored(), "");
  const Image b =
      screenshot("--scene eightball --question \"Shall I break?\" --seed " + std::to_string(other));
  ASSERT_EQ(a.width, 1280);
  ASSERT_EQ(b.width, 1280);
  const RoomOnScreen room = project(camera_);
  int inside = 0, outside = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (a.at(x, y) == b.at(x, y)) continue;
      const double dx = x - double(room.window.x), dy = y - double(room.window.y);
      (dx * dx + dy * dy < room.ball_radius * room.ball_radius * 0.16 ? inside : outside)++;
    }
  }
  EXPECT_GT(inside, 50) << "the letters differ";
  EXPECT_EQ(outside, 0) << "nothing else does";
}

TEST_F(RenderEightBallTest, ABlankQuestionIsRefused) {
  const std::string cmd = pool::test::xvfbRun() + std::string(" ") + POOL_BIN_DIR +
                          "/pool-client --screenshot " + png_ +
                          " --scene eightball --question \"  \" 2>/dev/null";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  EXPECT_EQ(loadPng(png_).width, 0) << "no picture written";
}

// The room's sidecar (it exited 2 before: "no balls to describe"): the camera, the ball, its
// answer window and the answer, each point where the picture shows it.
TEST_F(RenderEightBallTest, TheRoomsSidecarSaysWhereTheBallAndItsAnswerAre) {
  const Image image = view("--scene eightball --question \"Shall I break?\" --seed 3");
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(camera_.mirrored(), "");
  const auto info = readInfo(this->info());
  const ReportedCamera& camera = camera_;
  const auto& ball = info.at("eight_ball");
  EXPECT_EQ(ball.at("answer"), *room::answer("Shall I break?", 3));
  // Each point's pixel is where the reported camera puts its position (0.5 px of rounding).
  for (const char* part : {"centre", "window"}) {
    const auto& p = ball.at(part);
    ASSERT_TRUE(p.at("on_screen").get<bool>()) << part;
    const glm::vec3 at(p.at("pos")[0].get<float>(), p.at("pos")[1].get<float>(),
                       p.at("pos")[2].get<float>());
    const glm::vec3 px = camera.pixel(at);
    EXPECT_NEAR(p.at("px")[0].get<double>(), px.x, 0.5) << part;
    EXPECT_NEAR(p.at("px")[1].get<double>(), px.y, 0.5) << part;
  }
  // The window's pixel shows the blue answer triangle; the ball is the room's.
  const RoomOnScreen room = project(camera_);
  const auto& window = ball.at("window").at("px");
  const auto blue = [](const Rgb& p) { return shadeOf(p, kTriangle); };
  EXPECT_GT(countInDisc(image, window[0].get<double>(), window[1].get<double>(), 10.0, blue), 150);
  EXPECT_NEAR(ball.at("radius").get<double>(), render::EightBallRoom::ballRadius(), 1e-6);
  EXPECT_NEAR(ball.at("centre").at("px")[0].get<double>(), room.ball.x, 0.5);
}

}  // namespace
}  // namespace pool::client::test
