// Internal to pool_table: the triangle mesh parts of a table (slate, cushions, jaws, pockets,
// rails, trough).
#pragma once

#include <vector>

#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::table::detail {

/// Every mesh part of the table, in a fixed order: slate, cushion_<rail> ×6, jaw_<pocket> ×6,
/// pocket_<pocket> ×6, rail_<rail> ×6, trough. Triangles face the side a ball may be on.
std::vector<MeshPart> buildMeshParts(const TableSpec& spec);

/// Height of the trough floor at the head end (x = −slate half length), m.
double troughHeadZ();

}  // namespace pool::table::detail
