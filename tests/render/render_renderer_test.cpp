// The renderer in-process on an offscreen context: overlay lines on top, pocketed balls in the
// trough slots the table spec gives, and a ball's markings turning with its orientation.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <optional>

#include "client/render/offscreen.h"
#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "support/display_check.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

constexpr int kW = 640;
constexpr int kH = 360;

class RendererTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto s = render::rackScene();
    ASSERT_TRUE(static_cast<bool>(s)) << s.error();
    scene_ = std::move(*s);
    try {
      context_.emplace(kW, kH);
    } catch (const std::runtime_error& e) {
      POOL_NO_DISPLAY("no OpenGL context: " << e.what());
    }
    renderer_ = std::make_unique<render::Renderer>(scene_);
    camera_ = render::overviewCamera(scene_.geometry, float(kW) / float(kH));
  }
  Image frame(const render::Camera& camera) {
    context_->bind();
    renderer_->draw(camera, kW, kH);
    const auto rgb = context_->readRgb();
    context_->endFrame();
    Image image{kW, kH, {}};
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
      image.pixels.push_back({double(rgb[i]), double(rgb[i + 1]), double(rgb[i + 2])});
    }
    return image;
  }
  glm::vec3 toPixels(const render::Camera& camera, const Eigen::Vector3d& p) const {
    return render::projectToPixels(camera, kW, kH, glm::vec3(p.x(), p.y(), p.z()));
  }
  render::Scene scene_;
  std::optional<render::OffscreenContext> context_;
  std::unique_ptr<render::Renderer> renderer_;
  render::Camera camera_;
};

TEST_F(RendererTest, OverlayLinesAreDrawnUnlitOnTopOfTheBalls) {
  const Eigen::Vector3d apex = scene_.balls[1].pos;  // a rack ball: the line must cross over it
  const glm::vec3 magenta(1.0f, 0.0f, 1.0f);
  renderer_->setOverlay({{glm::vec3(-1.0f, float(apex.y()), float(apex.z())),
                          glm::vec3(1.2f, float(apex.y()), float(apex.z())), magenta}});
  const Image with = frame(camera_);
  const glm::vec3 px = toPixels(camera_, apex);
  const auto isMagenta = [](const Rgb& p) { return p[0] > 250 && p[1] < 5 && p[2] > 250; };
  EXPECT_GT(countInDisc(with, px.x, px.y, 2.5, isMagenta), 0) << "line over the ball";
  const glm::vec3 mid = toPixels(camera_, Eigen::Vector3d(0.0, apex.y(), apex.z()));
  EXPECT_GT(countInDisc(with, mid.x, mid.y, 2.5, isMagenta), 0) << "line over the felt";
  renderer_->setOverlay({});
  EXPECT_EQ(count(frame(camera_), isMagenta), 0);
}

TEST_F(RendererTest, PocketedBallsAreDrawnInTheTrough) {
  // The trough as promised (ball_trough.h): a row along the near (-y) side, in front of the near
  // rail's outer face, the balls' centres a radius under the slate's top, 2 R apart, the row of
  // 16 centred on the table's middle and filled in pocketing order from the foot (+x) end. Slot
  // i's centre: x = (15 - 2 i) R, y = -(w / 2 + cushion + rail) - R, z = -R, from the spec.
  const auto spec = table::loadTableSpec("wpa-9ft");  // rackScene's table
  ASSERT_TRUE(spec) << spec.error();
  const double r = spec->params.ball_radius;
  const double face = -(0.5 * spec->width + spec->cushion_width + spec->rail_width);
  const auto slot = [&](int i) {
    return glm::vec3(float((15 - 2 * i) * r), float(face - r), float(-r));
  };
  // The test's own camera, in front of the near side and above it, and its own projection.
  const render::Camera near_side{glm::vec3(0.2f, -1.5f, 0.45f), glm::vec3(0.2f, -0.75f, -0.03f),
                                 30.0f};
  ReportedCamera own;
  own.width = kW;
  own.height = kH;
  own.view = glm::lookAt(near_side.eye, near_side.target, glm::vec3(0.0f, 0.0f, 1.0f));
  own.projection = glm::perspective(glm::radians(near_side.fov_y_deg), float(kW) / float(kH),
                                    render::kNearPlane, render::kFarPlane);
  ASSERT_EQ(own.mirrored(), "");

  // The 6 goes down first, then the 2: the 6 in slot 0, the 2 in slot 1.
  std::vector<render::SceneBall> balls = scene_.balls;
  for (auto& b : balls) b.pocketed = b.id == 6;
  renderer_->setBalls(balls);
  for (auto& b : balls) b.pocketed = b.id == 2 || b.id == 6;
  renderer_->setBalls(balls);
  const Image image = frame(near_side);
  // A ball drawn in its slot covers the disc of 0.8 of its projected radius round the slot's
  // centre, and more than half of that disc shows its colour (the rest: its number's white circle
  // and the lamp's highlight). The centre as computed leaves out the few mm between the rail and
  // the ball the layout allows (under 0.2 R): the disc still lies inside the ball. A neighbour
  // 2 R away stays 0.2 of a radius clear of the disc: its colour there is at most an antialiased
  // pixel or two, under a tenth of the disc.
  const auto share = [&](int i, int id) {
    const glm::vec3 c = own.pixel(slot(i));
    const glm::vec3 top = own.pixel(slot(i) + glm::vec3(0.0f, 0.0f, float(r)));
    const double radius = 0.8 * glm::length(glm::vec2(top - c));
    const double area = std::numbers::pi * radius * radius;
    EXPECT_TRUE(own.inside(c, 20.0f)) << "slot " << i << " at " << c.x << ", " << c.y;
    return countInDisc(image, c.x, c.y, radius, [&](const Rgb& p) { return ballColour(id, p); }) /
           area;
  };
  EXPECT_GT(share(0, 6), 0.5) << "the 6, pocketed first, in the foot end's slot";
  EXPECT_GT(share(1, 2), 0.5) << "the 2 beside it";
  EXPECT_LT(share(0, 2), 0.1);
  EXPECT_LT(share(1, 6), 0.1);
  for (int id : {2, 6}) EXPECT_LT(share(2, id), 0.1) << "slot 2 is empty";
}

TEST_F(RendererTest, ABallsMarkingsTurnWithItsOrientation) {
  // Close over the 7 (maroon, a number on each side), looking straight down.
  render::SceneBall ball;
  for (const auto& b : scene_.balls) {
    if (b.id == 7) ball = b;
  }
  const Eigen::Vector3d p = ball.pos;
  const render::Camera close{glm::vec3(p.x(), p.y() - 0.001, p.z() + 0.25),
                             glm::vec3(p.x(), p.y(), p.z()), 30.0f};
  const auto look = [&](const Eigen::Quaterniond& q) {
    std::vector<render::SceneBall> balls = scene_.balls;
    for (auto& b : balls) {
      if (b.id == 7) b.orientation = q;
    }
    renderer_->setBalls(balls);
    return frame(close);
  };
  const Image up = look(Eigen::Quaterniond(
      Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitY())));  // number on top
  const Image side = look(Eigen::Quaterniond::Identity());                   // number faces along x
  const glm::vec3 c = toPixels(close, p);
  EXPECT_GT(countInDisc(up, c.x, c.y, 20.0, isWhite), 200) << "number circle seen from above";
  const auto ink = [](const Rgb& px) { return std::max({px[0], px[1], px[2]}) < 60.0; };
  EXPECT_GT(countInDisc(up, c.x, c.y, 12.0, ink), 10) << "the number's ink inside the circle";
  EXPECT_LT(countInDisc(side, c.x, c.y, 20.0, isWhite),
            countInDisc(up, c.x, c.y, 20.0, isWhite) / 3)
      << "turned away, the top shows maroon";
  // The ball is about 75 px across at this distance: most of it is maroon either way.
  const auto maroon = [](const Rgb& px) { return ballColour(7, px); };
  EXPECT_GT(countInDisc(side, c.x, c.y, 60.0, maroon), 3000);
  EXPECT_GT(countInDisc(side, c.x, c.y, 60.0, maroon), countInDisc(up, c.x, c.y, 60.0, maroon));
}

}  // namespace
}  // namespace pool::client::test
