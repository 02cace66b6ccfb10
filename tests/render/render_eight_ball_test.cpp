// pool-client --screenshot --scene eightball: the giant 8-ball on its stool, the blue answer
// triangle in its dark window facing the viewer, and the answer's text on it.
#include <gtest/gtest.h>

#include "client/render/eight_ball_room.h"
#include "client/room/magic_eight_ball.h"
#include "support/screenshot_fixture.h"

namespace pool::client::test {
namespace {

using RenderEightBallTest = ScreenshotTest;

constexpr Rgb kTriangle{0.10, 0.22, 0.85};
constexpr Rgb kWood{0.34, 0.17, 0.07};

/// The window's centre and the ball's radius on screen, from the room's default camera and its
/// ball. The window is the point of the ball's surface nearest the viewer (it faces them: the
/// room's promise), found here from the eye and the ball alone, not from the room's own code.
struct RoomOnScreen {
  glm::vec3 window;
  glm::vec3 ball;
  double ball_radius;
};

RoomOnScreen project(int width, int height) {
  const auto camera = render::EightBallRoom::defaultCamera();
  const glm::vec3 ball = render::EightBallRoom::ballCentre();
  const glm::vec3 side = glm::vec3(render::EightBallRoom::ballRadius(), 0, 0);
  const glm::vec3 c = render::projectToPixels(camera, width, height, ball);
  const glm::vec3 e = render::projectToPixels(camera, width, height, ball + side);
  const glm::vec3 toward_viewer = glm::normalize(camera.eye - ball);
  const glm::vec3 window = ball + toward_viewer * render::EightBallRoom::ballRadius();
  return {render::projectToPixels(camera, width, height, window), c,
          glm::length(glm::vec2(e) - glm::vec2(c))};
}

TEST_F(RenderEightBallTest, TheBallOnItsStoolShowsTheAnswerTriangleWithText) {
  const Image image = screenshot("--scene eightball --question \"Shall I break?\" --seed 3");
  ASSERT_EQ(image.width, 1280);
  const RoomOnScreen room = project(image.width, image.height);
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
  const Image a = screenshot("--scene eightball --question \"Shall I break?\" --seed 0");
  const Image b =
      screenshot("--scene eightball --question \"Shall I break?\" --seed " + std::to_string(other));
  ASSERT_EQ(a.width, 1280);
  ASSERT_EQ(b.width, 1280);
  const RoomOnScreen room = project(a.width, a.height);
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
  const std::string cmd = std::string("xvfb-run -a ") + POOL_BIN_DIR +
                          "/pool-client --screenshot " + png_ +
                          " --scene eightball --question \"  \" 2>/dev/null";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  EXPECT_EQ(loadPng(png_).width, 0) << "no picture written";
}

TEST_F(RenderEightBallTest, ASidecarIsRefusedForTheRoomWithoutWritingAnything) {
  const std::string json = png_ + ".json";
  const std::string cmd = std::string("env -u DISPLAY ") + POOL_BIN_DIR +
                          "/pool-client --screenshot " + png_ +
                          " --scene eightball --screenshot-info " + json + " 2>/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()) >> 8, 2);
  EXPECT_EQ(loadPng(png_).width, 0) << "no picture written";
  EXPECT_NE(::access(json.c_str(), F_OK), 0) << "no sidecar written";
}

}  // namespace
}  // namespace pool::client::test
