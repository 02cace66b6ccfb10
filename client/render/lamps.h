// The two lamps over the table: where their lights hang, their spot cones, and their shades.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "client/render/mesh.h"
#include "table/table_geometry.h"

namespace pool::render {

/// Light height above the slate, m (a little over a metre, as over a real table).
inline constexpr float kLampHeight = 1.25f;
/// Spot cone: full light inside the inner half-angle, none beyond the outer one, degrees.
inline constexpr float kSpotInnerDeg = 30.0f;
inline constexpr float kSpotOuterDeg = 62.0f;

/// The two light positions, over the head and foot halves of the table (table frame, m).
std::array<glm::vec3, 2> lampPositions(const pool::table::TableGeometry& geometry);

/// A shade around a light at the origin: an open cone above it and a rod up to the ceiling.
MeshData lampShade();
/// The glowing bulb face under the shade: a disc at the light, radius 1 (scale it).
inline constexpr float kBulbRadius = 0.05f;

}  // namespace pool::render
