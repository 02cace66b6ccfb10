// What the bot knows of the table: spec, collision geometry, the rules' view and where to aim at
// each pocket.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/result.h"
#include "rules/game_rules.h"
#include "rules/table_context.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::bot {

using Vec2 = Eigen::Vector2d;

/// One pocket as a target for an object ball. Table frame, metres.
struct PocketTarget {
  std::string name;  ///< the pocket's name, as calls spell it (rules::pocketNames)
  Vec2 mouth;        ///< midpoint between the two jaw points (where the rail noses end)
  Vec2 hole;         ///< centre of the hole in the slate
  Vec2 outward;      ///< unit, from the table into the pocket
  bool corner = false;
};

/// A loaded table as the AI uses it.
struct TableView {
  table::TableSpec spec;
  table::TableGeometry geometry;
  rules::TableContext context;  ///< spots, ball radius, pocket holes
  std::vector<PocketTarget> pockets;
  rules::GameRules rules;  ///< the game played on it (8-ball unless the match says otherwise)

  double radius() const { return context.ball_radius; }  ///< ball radius, m
  double halfLength() const { return spec.length / 2; }  ///< playing surface half extent in x, m
  double halfWidth() const { return spec.width / 2; }    ///< playing surface half extent in y, m
  double headStringX() const { return context.spots.head_string_x; }  ///< m
};

/// Builds the view of a spec and its geometry (pocket targets from the holes and rail noses).
TableView makeTableView(table::TableSpec spec, table::TableGeometry geometry);

/// Loads a table by spec name ("wpa-9ft") or path, with its collision mesh.
Result<TableView> loadTableView(const std::string& name);

/// The index of pocket `name` in `view.pockets`, or -1.
int pocketIndex(const TableView& view, const std::string& name);

}  // namespace pool::bot
