// The table part of the plot: rails, cushions, cloth, pockets, nose lines, diamonds, spots.
#pragma once

#include <string>

#include "scenario/svg_canvas.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::scenario {

/// Half-extents of the whole table (rails included), metres.
Eigen::Vector2d tableOuterHalfSize(const table::TableSpec& spec,
                                   const table::TableGeometry& geometry);

/// SVG elements of the table seen from above, to scale.
std::string drawTable(const SvgView& view, const table::TableSpec& spec,
                      const table::TableGeometry& geometry);

}  // namespace pool::scenario
