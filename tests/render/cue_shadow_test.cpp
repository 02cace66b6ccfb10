// The cue's shadow: its axis projected from the lamp onto the slate, on the playing surface only.
#include "client/render/cue_shadow.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace pool::render {
namespace {

constexpr float kR = 0.028575f;

TEST(CueShadowTest, StripFollowsTheCuesAxisProjectedFromTheLamp) {
  const std::array<glm::vec3, 1> lamp{glm::vec3(-0.635f, 0.0f, 0.95f)};
  // A level cue at ball height pointing along +y, beside the lamp, its tip at y = 0.2.
  CuePlacement cue;
  cue.forward = {0.0f, 1.0f, 0.0f};
  cue.tip = {-0.4f, 0.2f, kR};
  cue.butt = cue.tip - cue.forward * 1.47f;
  const auto strip = cueShadow(lamp, cue, 1.27f, 0.635f, 0.38f);
  ASSERT_FALSE(strip.empty());
  for (const ShadowBlob& piece : strip) {
    EXPECT_FALSE(piece.soft_ends);
    EXPECT_LE(std::abs(piece.centre.y), 0.635f);  // on the playing surface only
    // A point of the cue at height h projects to lamp + (p − lamp) · H / (H − h): the pieces lie
    // on the line x = lamp.x + (cue.x − lamp.x) · H / (H − h), farther from the lamp than the cue.
    const float h = cue.tip.z;  // level: every point at the tip's height
    const float x = -0.635f + (cue.tip.x + 0.635f) * 0.95f / (0.95f - h);
    EXPECT_NEAR(piece.centre.x, x, 2e-3f);
    EXPECT_GT(piece.darkness, 0.0f);
  }
}

TEST(CueShadowTest, OverTheRailsTheStripLiesOnTheRailTopBetweenTheNoseAndTheEdge) {
  const std::array<glm::vec3, 1> lamp{glm::vec3(-0.635f, 0.0f, 0.95f)};
  // The cue over the long rail: aimed along −y from beyond the table, raised 10 cm.
  CuePlacement cue;
  cue.forward = {0.0f, -1.0f, 0.0f};
  cue.tip = {-0.5f, 0.4f, 0.1f};
  cue.butt = cue.tip - cue.forward * 1.47f;
  const RailExtent rails{1.27f, 0.635f, 0.05f, 0.1f, 0.0413f};
  const auto strip = cueShadowOnRails(lamp, cue, rails, 0.38f);
  ASSERT_FALSE(strip.empty());
  const float h = cue.tip.z, top = rails.top;
  for (const ShadowBlob& piece : strip) {
    EXPECT_EQ(piece.z, top);
    EXPECT_GT(std::abs(piece.centre.y), 0.635f);  // beyond the nose line
    EXPECT_LE(std::abs(piece.centre.y), 0.785f);  // not past the table's edge
    // Projected onto the plane z = top: x = lamp.x + (cue.x − lamp.x) · (H − top) / (H − h).
    const float x = -0.635f + (cue.tip.x + 0.635f) * (0.95f - top) / (0.95f - h);
    EXPECT_NEAR(piece.centre.x, x, 2e-3f);
  }
  // None of it over the felt, which cueShadow covers.
  for (const ShadowBlob& piece : cueShadow(lamp, cue, 1.27f, 0.635f, 0.38f)) {
    EXPECT_EQ(piece.z, 0.0f);
    EXPECT_LE(std::abs(piece.centre.y), 0.635f);
  }
}

}  // namespace
}  // namespace pool::render
