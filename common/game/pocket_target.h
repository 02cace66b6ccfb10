// Where to send an object ball into each pocket: its mouth between the jaws, its hole, outward.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "table/table_geometry.h"

namespace pool::game {

/// One pocket as a target for an object ball. Table frame, metres.
struct PocketTarget {
  std::string name;         ///< the pocket's name, as calls spell it (rules::pocketNames)
  Eigen::Vector2d mouth;    ///< midpoint between the two jaw points (where the rail noses end)
  Eigen::Vector2d hole;     ///< centre of the hole in the slate
  Eigen::Vector2d outward;  ///< unit, from the table into the pocket
  bool corner = false;
};

/// The target of every pocket hole of `geometry`, in the geometry's order.
std::vector<PocketTarget> pocketTargets(const table::TableGeometry& geometry);

}  // namespace pool::game
