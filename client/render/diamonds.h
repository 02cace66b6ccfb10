// The eighteen diamonds (sights) inlaid in the rails: six on each long rail at every eighth of
// the length between the pockets, three on each end rail at every quarter of the width, each
// across the middle of the wooden rail's top.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "client/render/mesh.h"
#include "table/table_geometry.h"

namespace pool::render {

/// How far the rails reach: the nose lines' rectangle, the cushion and rail widths beyond them and
/// the rail top's height (from the table's mesh parts).
struct RailExtent {
  float half_length = 0.0f;    ///< nose line of the end rails, |x|, m
  float half_width = 0.0f;     ///< nose line of the long rails, |y|, m
  float cushion_width = 0.0f;  ///< nose to the back of the cushion (the rail's inner edge), m
  float rail_width = 0.0f;     ///< the wooden rail's width, m
  float top = 0.0f;            ///< the rail top above the slate, m
};

/// The rails of `geometry`, read from its rail_* mesh parts (outer edge and top) and its size.
/// `cushion_width` is the spec's (nose to the rail's inner edge).
RailExtent railExtent(const pool::table::TableGeometry& geometry, float cushion_width);

/// Centres of the 18 diamonds on the rail tops (table frame, m): long rails first (−y then +y,
/// head to foot), then the end rails (head then foot, −y to +y).
std::vector<glm::vec3> diamondPositions(const RailExtent& rails);

/// One diamond inlay centred at the origin on a rail top, its long diagonal along x: a flat
/// rhombus facing +z (rotate it a quarter turn on the end rails).
MeshData diamondInlay();
/// The inlay's half diagonals, m.
inline constexpr float kDiamondHalfLong = 0.013f;
inline constexpr float kDiamondHalfShort = 0.0065f;

}  // namespace pool::render
