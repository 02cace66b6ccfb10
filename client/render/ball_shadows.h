// The balls' shadows on the felt: for each ball and lamp, the ellipse where the ball hides the
// lamp's light (the sphere's shadow cone cut by the slate), darker the more of the felt's light
// that lamp gives; and a soft contact shadow right under each ball. A ball at a cushion also
// darkens the cushion beside it, away from the nearest lamp. Pure (no GL).
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace pool::render {

/// A soft dark ellipse on the slate, or on the rails' and cushions' tops (table frame, m).
struct ShadowBlob {
  glm::vec2 centre{0.0f};
  glm::vec2 along{1.0f, 0.0f};  ///< unit: the long axis, away from the lamp
  float half_along = 0.0f;      ///< m
  float half_across = 0.0f;     ///< m
  float darkness = 0.0f;        ///< share of the felt's light removed at the centre, 0–1
  bool soft_ends = true;        ///< false: a piece of a strip, soft only across (the cue's shadow)
  /// The surface's height above the slate: 0 the felt; above it, the rails' top, where the
  /// shadow layer draws it only outside the playing surface and inside the table's edge.
  float z = 0.0f;
};

/// The ellipse where a ball of radius `radius` centred at `ball` hides a point light at `lamp`
/// from the slate (z = 0); darkness left 0.
ShadowBlob castShadow(glm::vec3 lamp, glm::vec3 ball, float radius);

/// Every shadow of the balls at `balls` (centres on the slate) under `lamps`: one per ball and
/// lamp that lights the felt there, and one contact shadow per ball. `ambient`: the felt's light
/// from elsewhere (share of the albedo).
std::vector<ShadowBlob> ballShadows(std::span<const glm::vec3> lamps,
                                    std::span<const glm::vec3> balls, float radius, float ambient);

/// The balls' shadows on the cushions: for a ball within a radius of a nose line (|x| =
/// `half_length`, |y| = `half_width`), the cushion beside it darkened as the felt is under a ball
/// (the light it hides there), the darkest part shifted along the rail away from the nearest lamp,
/// fading with the gap between ball and cushion. Blobs in the plane of the rails' top (z = `top`),
/// which the shadow layer draws only past the nose lines.
std::vector<ShadowBlob> ballShadowsOnCushions(std::span<const glm::vec3> lamps,
                                              std::span<const glm::vec3> balls, float radius,
                                              float half_length, float half_width, float top);

}  // namespace pool::render
