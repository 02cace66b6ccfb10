// The bot's view of a table: the game kit's loaded table with the rules beside it.
#include "client/bot/ai/table_view.h"

#include <utility>

namespace pool::bot {

TableView tableViewOf(game::LoadedTable table) {
  TableView view;
  static_cast<game::LoadedTable&>(view) = std::move(table);
  return view;
}

TableView makeTableView(table::TableSpec spec, table::TableGeometry geometry) {
  return tableViewOf(game::makeLoadedTable(std::move(spec), std::move(geometry)));
}

Result<TableView> loadTableView(const std::string& name) {
  auto loaded = game::loadTable(name);
  if (!loaded) return Result<TableView>::fail(loaded.error());
  return Result<TableView>::ok(tableViewOf(std::move(*loaded)));
}

}  // namespace pool::bot
