// Ball shadows: the ellipse of a sphere's shadow cone under a point light, and which lamps cast
// them.
#include "client/render/ball_shadows.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace pool::render {
namespace {

constexpr float kR = 0.028575f;

TEST(BallShadowsTest, ShadowLiesBeyondTheBallAwayFromTheLight) {
  const glm::vec3 lamp(0.0f, 0.0f, 1.0f);
  const glm::vec3 ball(0.5f, 0.2f, kR);
  const ShadowBlob s = castShadow(lamp, ball, kR);
  const glm::vec2 away = glm::normalize(glm::vec2(ball));
  EXPECT_NEAR(glm::dot(s.along, away), 1.0f, 1e-5f);
  // The tangent rays from the light graze the sphere and meet the slate at the ellipse's ends:
  // check the far end against the ray through the sphere's far tangent point, computed here in
  // the vertical plane through light and ball.
  const float h = glm::length(glm::vec2(ball));
  const float drop = lamp.z - ball.z;
  const float tilt = std::atan2(h, drop), spread = std::asin(kR / std::hypot(h, drop));
  const float far = lamp.z * std::tan(tilt + spread);
  EXPECT_NEAR(glm::dot(s.centre, away) + s.half_along, far, 1e-4f);
  EXPECT_GT(glm::dot(s.centre, away), h);  // its middle beyond the ball's centre
  EXPECT_NEAR(s.half_across, kR, 0.1f * kR);
}

TEST(BallShadowsTest, OneShadowPerLightingLampAndAContactShadow) {
  const std::array<glm::vec3, 2> lamps{glm::vec3(-0.635f, 0.0f, 0.95f),
                                       glm::vec3(0.635f, 0.0f, 0.95f)};
  // Near the head lamp only: its shadow and the contact shadow (the foot lamp's cone is far).
  const std::array<glm::vec3, 1> ball{glm::vec3(-0.9f, 0.2f, kR)};
  const auto blobs = ballShadows(lamps, ball, kR, 0.22f);
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_GT(blobs[0].darkness, 0.5f);
  EXPECT_LT(blobs[0].centre.x, -0.9f);  // away from the head lamp, toward the head rail
}

TEST(BallShadowsTest, ABallAtACushionDarkensTheCushionAwayFromTheNearestLamp) {
  constexpr float kHalfLength = 1.27f, kHalfWidth = 0.635f, kTop = 0.041f;
  const std::array<glm::vec3, 2> lamps{glm::vec3(-0.635f, 0.0f, 0.95f),
                                       glm::vec3(0.635f, 0.0f, 0.95f)};
  // Touching the +y cushion 18.5 cm toward the middle from the head lamp.
  const std::array<glm::vec3, 1> touching{glm::vec3(-0.45f, kHalfWidth - kR, kR)};
  const auto blobs = ballShadowsOnCushions(lamps, touching, kR, kHalfLength, kHalfWidth, kTop);
  ASSERT_EQ(blobs.size(), 1u);
  const ShadowBlob& s = blobs[0];
  EXPECT_FLOAT_EQ(s.z, kTop);
  EXPECT_NEAR(std::abs(s.along.x), 1.0f, 1e-6f) << "along the long rail";
  EXPECT_GT(s.centre.y, kHalfWidth) << "on the cushion past the nose";
  EXPECT_LT(s.centre.y - s.half_across, kHalfWidth) << "from the nose line on";
  EXPECT_GT(s.centre.x, touching[0].x) << "shifted away from the head lamp (toward +x)";
  EXPECT_LT(s.centre.x - s.half_along, touching[0].x) << "and still beside the ball";
  EXPECT_GT(s.darkness, 0.3f);

  // Half a radius off the -y cushion: fainter; 1.5 R off, or in the middle: nothing.
  const std::array<glm::vec3, 1> near{glm::vec3(-0.45f, -(kHalfWidth - 1.5f * kR), kR)};
  const auto fainter = ballShadowsOnCushions(lamps, near, kR, kHalfLength, kHalfWidth, kTop);
  ASSERT_EQ(fainter.size(), 1u);
  EXPECT_LT(fainter[0].centre.y, -kHalfWidth) << "the -y cushion";
  EXPECT_LT(fainter[0].darkness, s.darkness);
  EXPECT_GT(fainter[0].darkness, 0.0f);
  const std::array<glm::vec3, 2> apart{glm::vec3(-0.45f, kHalfWidth - 2.5f * kR, kR),
                                       glm::vec3(0.1f, 0.1f, kR)};
  EXPECT_TRUE(ballShadowsOnCushions(lamps, apart, kR, kHalfLength, kHalfWidth, kTop).empty());
  // In a corner: both cushions.
  const std::array<glm::vec3, 1> corner{
      glm::vec3(kHalfLength - 1.2f * kR, kHalfWidth - 1.2f * kR, kR)};
  EXPECT_EQ(ballShadowsOnCushions(lamps, corner, kR, kHalfLength, kHalfWidth, kTop).size(), 2u);
}

}  // namespace
}  // namespace pool::render
