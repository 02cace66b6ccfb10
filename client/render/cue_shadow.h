// The cue's shadow on the felt and on the cushions and rails: its axis projected from each lamp
// that lights the surface under it, as a strip of pieces as wide as the cue's shadow there. Pure
// (no GL).
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "client/render/ball_shadows.h"
#include "client/render/cue_pose.h"
#include "client/render/diamonds.h"

namespace pool::render {

/// The pieces of the cue's shadow that fall on the playing surface (|x| ≤ half_length,
/// |y| ≤ half_width); `ambient` as for ballShadows.
std::vector<ShadowBlob> cueShadow(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                                  float half_length, float half_width, float ambient);

/// The pieces that fall on the cushions and rails round the playing surface: the axis projected
/// onto the plane of the rails' top (z = rails.top, the blobs' z), where that lies between the
/// nose lines and the table's outer edge.
std::vector<ShadowBlob> cueShadowOnRails(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                                         const RailExtent& rails, float ambient);

}  // namespace pool::render
