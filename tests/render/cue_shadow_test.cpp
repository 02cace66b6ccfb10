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

}  // namespace
}  // namespace pool::render
