// The cue's shadow on the felt: its axis projected from each lamp that lights the felt under it
// onto the slate, as a strip of pieces as wide as the cue's shadow there. Pure (no GL).
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "client/render/ball_shadows.h"
#include "client/render/cue_pose.h"

namespace pool::render {

/// The pieces of the cue's shadow that fall on the playing surface (|x| ≤ half_length,
/// |y| ≤ half_width); `ambient` as for ballShadows.
std::vector<ShadowBlob> cueShadow(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                                  float half_length, float half_width, float ambient);

}  // namespace pool::render
