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
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  for (const glm::vec3& ball : balls) {
    for (const glm::vec3& lamp : lamps) {
      // The light at the shadow's own centre decides how dark it is.
      ShadowBlob blob = castShadow(lamp, ball, radius);
      const glm::vec3 at(blob.centre, 0.0f);
      float here = ambient;
      for (const glm::vec3& other : lamps) here += lampLight(other, at, up);
      const float share = lampLight(lamp, at, up) / here;
      if (share < kMinShare) continue;
      blob.darkness = std::min(share, 1.0f);
      out.push_back(blob);
    }
    out.push_back({glm::vec2(ball.x, ball.y), glm::vec2(1.0f, 0.0f), radius * kContactSize,
                   radius * kContactSize, kContactDarkness});
  }
  return out;
}

}  // namespace pool::render
