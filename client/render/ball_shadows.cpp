// Shadow ellipses from the geometry of a sphere's shadow cone.
#include "client/render/ball_shadows.h"

#include <algorithm>
#include <cmath>

#include "client/render/lamps.h"

namespace pool::render {

namespace {

constexpr float kContactDarkness = 0.45f;  // under the ball, where little light reaches
constexpr float kContactSize = 0.75f;      // contact shadow radius, ball radii
constexpr float kMinShare = 0.02f;         // lamps giving less of the light cast no shadow
constexpr float kCushionDarkness = 0.5f;   // the cushion's face at a touching ball
constexpr float kCushionReach = 1.0f;      // gaps (ball to nose line, radii) that still darken

/// How much of the light at `at` (on a surface facing up) comes from `lamp`.
float lampShare(std::span<const glm::vec3> lamps, const glm::vec3& lamp, const glm::vec3& at,
                float ambient) {
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  float here = ambient;
  for (const glm::vec3& other : lamps) here += lampLight(other, at, up);
  return lampLight(lamp, at, up) / here;
}

}  // namespace

ShadowBlob castShadow(glm::vec3 lamp, glm::vec3 ball, float radius) {
  ShadowBlob blob;
  const glm::vec2 offset(ball.x - lamp.x, ball.y - lamp.y);
  const float horizontal = glm::length(offset);
  blob.along = horizontal > 1e-6f ? offset / horizontal : glm::vec2(1.0f, 0.0f);
  const float drop = lamp.z - ball.z;  // the light's height over the ball's centre
  const float distance = std::sqrt(horizontal * horizontal + drop * drop);
  // The cone from the light around the sphere: its axis at `tilt` from the vertical, half-angle
  // `spread`; its edges meet the slate at lamp.z · tan(tilt ∓ spread) from under the light.
  const float tilt = std::atan2(horizontal, drop);
  const float spread = std::asin(std::min(radius / distance, 0.999f));
  const float near_edge = lamp.z * std::tan(tilt - spread);
  const float far_edge = lamp.z * std::tan(std::min(tilt + spread, 1.5f));
  const glm::vec2 foot(lamp.x, lamp.y);
  blob.centre = foot + blob.along * (near_edge + far_edge) * 0.5f;
  blob.half_along = (far_edge - near_edge) * 0.5f;
  // Across: the cone's width where its axis meets the slate.
  blob.half_across = radius * (lamp.z / std::cos(tilt)) / distance;
  return blob;
}

std::vector<ShadowBlob> ballShadows(std::span<const glm::vec3> lamps,
                                    std::span<const glm::vec3> balls, float radius, float ambient) {
  std::vector<ShadowBlob> out;
  for (const glm::vec3& ball : balls) {
    for (const glm::vec3& lamp : lamps) {
      // The light at the shadow's own centre decides how dark it is.
      ShadowBlob blob = castShadow(lamp, ball, radius);
      const float share = lampShare(lamps, lamp, glm::vec3(blob.centre, 0.0f), ambient);
      if (share < kMinShare) continue;
      blob.darkness = std::min(share, 1.0f);
      out.push_back(blob);
    }
    out.push_back({glm::vec2(ball.x, ball.y), glm::vec2(1.0f, 0.0f), radius * kContactSize,
                   radius * kContactSize, kContactDarkness});
  }
  return out;
}

std::vector<ShadowBlob> ballShadowsOnCushions(std::span<const glm::vec3> lamps,
                                              std::span<const glm::vec3> balls, float radius,
                                              float half_length, float half_width, float top) {
  std::vector<ShadowBlob> out;
  for (const glm::vec3& ball : balls) {
    // The cushion's face beside the ball, for each nose line the ball is near. (The lamps hang
    // too high for a ball's own shadow cone to reach past a nose: from a ball at a cushion, the
    // cone's edge comes down to the cushion's height short of the nose line.)
    const glm::vec3* nearest = nullptr;
    for (const glm::vec3& lamp : lamps) {
      const auto d = [&](const glm::vec3& l) { return glm::length(glm::vec2(ball - l)); };
      if (!nearest || d(lamp) < d(*nearest)) nearest = &lamp;
    }
    for (int axis = 0; axis < 2; ++axis) {
      const float nose = axis == 0 ? half_length : half_width;
      const float at = axis == 0 ? ball.x : ball.y;
      const float gap = nose - std::abs(at) - radius;  // ball surface to the nose line
      if (gap > kCushionReach * radius) continue;
      const float side = at < 0.0f ? -1.0f : 1.0f;
      glm::vec2 across(0.0f), rail(0.0f);
      across[axis] = side;
      rail[1 - axis] = 1.0f;
      // Along the rail, away from the nearest lamp (straight across: no shift).
      float away = 0.0f;
      if (nearest) {
        const float offset = glm::dot(glm::vec2(ball - *nearest), rail);
        away = std::clamp(offset / (2.0f * radius), -1.0f, 1.0f);
      }
      ShadowBlob blob;
      glm::vec2 centre(ball.x, ball.y);
      centre[axis] = side * nose;
      blob.centre = centre + across * (0.5f * radius) + rail * (0.7f * radius * away);
      blob.along = rail;
      blob.half_along = 1.6f * radius;
      blob.half_across = 1.0f * radius;
      blob.darkness = kCushionDarkness * (1.0f - std::max(gap, 0.0f) / (kCushionReach * radius));
      blob.z = top;
      out.push_back(blob);
    }
  }
  return out;
}

}  // namespace pool::render
