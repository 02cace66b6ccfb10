// One table as a match needs it: spec, collision geometry, the rules' view, and fresh racks.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "physics/ball.h"
#include "rules/table_context.h"
#include "table/rack.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::server {

/// A loaded table, shared read-only by every match played on it.
struct TableKit {
  table::TableSpec spec;
  table::TableGeometry geometry;
  rules::TableContext context;  ///< spots, ball radius, pocket holes
};

/// Loads spec and geometry of `name` ("wpa-9ft", or a path to a spec file).
Result<std::shared_ptr<const TableKit>> loadTableKit(const std::string& name);

/// How far behind the head spot (toward the head cushion) the server puts the breaking cue ball,
/// m. The rules want a cue ball in hand strictly behind the head string, which runs through the
/// head spot.
inline constexpr double kBreakCueSetback = 0.01;

/// A fresh rack of `type` at rest: the object balls from the foot spot, laid out by `generator`
/// from `seed` (table::rackFor), and the cue ball kBreakCueSetback behind the head spot. In id
/// order.
std::vector<physics::Ball> rackLayout(
    const TableKit& kit, std::uint64_t seed, table::RackType type = table::RackType::EightBall,
    table::RackGenerator generator = table::RackGenerator::Frozen);

}  // namespace pool::server
