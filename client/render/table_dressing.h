// What makes the collision mesh look like a piece of furniture: wooden rail tops cut round the
// pockets with a rounded outer edge, the apron and its underside, the legs, and the pockets'
// leather liners and rims. Pure (no GL): the generator writes one per table spec to
// assets/hall/<table>.obj and the renderer reads it (or builds it for a table without one).
#pragma once

#include <vector>

#include "client/render/mesh.h"
#include "table/table_geometry.h"

namespace pool::render {

/// How deep a pocket's liner goes under the slate, m (its bottom a cup below that).
inline constexpr float kLinerDepth = 0.10f;
/// The leather rim round a pocket's cut on the rail top: its width, m.
inline constexpr float kRimWidth = 0.014f;
/// The rail tops (and the rims and diamonds on them) sit this far above the collision rails and
/// the jaws' tops, which they cover, m.
inline constexpr float kRailCapLift = 0.0004f;
/// The quarter-round on the rails' outer edge, m.
inline constexpr float kRailRound = 0.022f;

/// The dressing of `geometry` (its rails as railExtent reads them; `cushion_width` the spec's):
/// parts rail_top, rail_edge, apron, underside, leg, pocket_liner, pocket_rim. The same parts for
/// the same geometry.
std::vector<NamedMesh> tableDressing(const pool::table::TableGeometry& geometry,
                                     float cushion_width);

}  // namespace pool::render
