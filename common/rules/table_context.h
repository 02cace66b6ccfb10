// What the rules know of the table: its spec, spots and strings, ball radius and pocket holes.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "table/rack.h"
#include "table/snooker_spots.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::rules {

/// The table as the rules see it. Table frame (origin at the centre, +x toward the foot), metres.
struct TableContext {
  table::TableSpec spec;
  table::Spots spots;                    ///< head string, foot spot
  double ball_radius = 0.028575;         ///< m
  std::vector<table::PocketHole> holes;  ///< empty: placement checks do not look at pocket holes
  std::optional<table::SnookerSpots> snooker;  ///< a snooker table's baulk line, D and spots
};

/// The context of a spec: spots from table::spotsFor (and a snooker table's marks), the spec's
/// ball radius, no pocket holes.
TableContext tableContext(const table::TableSpec& spec);

/// As above, and the pocket holes of the geometry (a cue ball placed over one is refused).
TableContext tableContext(const table::TableSpec& spec, const table::TableGeometry& geometry);

/// The six pocket names, as events and calls spell them.
const std::vector<std::string_view>& pocketNames();

/// True for one of the six pocket names.
bool isPocketName(std::string_view name);

}  // namespace pool::rules
