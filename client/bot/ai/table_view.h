// What the bot knows of a game: the loaded table (game/loaded_table.h) and the rules played on it.
#pragma once

#include <string>

#include "core/result.h"
#include "game/loaded_table.h"
#include "rules/game_rules.h"

namespace pool::bot {

using Vec2 = Eigen::Vector2d;
using game::PocketTarget;

/// A loaded table and the game played on it, as the AI uses them.
struct TableView : game::LoadedTable {
  rules::GameRules rules;  ///< the game played on it (8-ball unless the match says otherwise)
};

/// The view of `table` for 8-ball (set `rules` for another game).
TableView tableViewOf(game::LoadedTable table);

/// Builds the view of a spec and its geometry (pocket targets from the holes and rail noses).
TableView makeTableView(table::TableSpec spec, table::TableGeometry geometry);

/// Loads a table by spec name ("wpa-9ft") or path, with its collision mesh.
Result<TableView> loadTableView(const std::string& name);

}  // namespace pool::bot
