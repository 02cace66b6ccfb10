// A table loaded once for everything that plays on it: spec, collision geometry, the rules' view
// (spots, ball radius, pocket holes) and the pocket targets.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "game/pocket_target.h"
#include "rules/table_context.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::game {

/// A loaded table: what the server's matches, the bot, the window and the tools read of it.
struct LoadedTable {
  table::TableSpec spec;
  table::TableGeometry geometry;
  rules::TableContext context;        ///< spots, ball radius, pocket holes
  std::vector<PocketTarget> pockets;  ///< one per pocket hole, in the geometry's order

  double radius() const { return context.ball_radius; }  ///< ball radius, m
  double halfLength() const { return spec.length / 2; }  ///< playing surface half extent in x, m
  double halfWidth() const { return spec.width / 2; }    ///< playing surface half extent in y, m
  double headStringX() const { return context.spots.head_string_x; }  ///< m
};

/// The loaded table of a spec and its geometry (the rules' view and the pocket targets derived).
LoadedTable makeLoadedTable(table::TableSpec spec, table::TableGeometry geometry);

/// Loads a table by spec name ("wpa-9ft") or path, with its collision mesh. The error names the
/// table ("table NAME: why").
Result<LoadedTable> loadTable(const std::string& name);

/// The geometry of a spec already read (its coefficients perhaps changed since, as a scenario's
/// are): its collision mesh where the spec names one that exists, else the geometry generated
/// from the spec, as pool-tablegen writes it.
Result<table::TableGeometry> tableGeometry(const table::TableSpec& spec);

/// loadTable's table, shared read-only (by every match a server plays on it).
Result<std::shared_ptr<const LoadedTable>> loadSharedTable(const std::string& name);

/// The index of pocket `name` in `table.pockets`, or -1.
int pocketIndex(const LoadedTable& table, const std::string& name);

}  // namespace pool::game
