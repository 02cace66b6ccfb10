// Loading a table once: spec, geometry, the rules' view and the pocket targets.
#include "game/loaded_table.h"

#include <filesystem>
#include <system_error>
#include <utility>

namespace pool::game {

LoadedTable makeLoadedTable(table::TableSpec spec, table::TableGeometry geometry) {
  LoadedTable loaded;
  loaded.context = rules::tableContext(spec, geometry);
  loaded.pockets = pocketTargets(geometry);
  loaded.spec = std::move(spec);
  loaded.geometry = std::move(geometry);
  return loaded;
}

Result<LoadedTable> loadTable(const std::string& name) {
  auto spec = table::loadTableSpec(name);
  if (!spec) return Result<LoadedTable>::fail("table " + name + ": " + spec.error());
  auto geometry = table::loadTableGeometry(*spec);
  if (!geometry) return Result<LoadedTable>::fail("table " + name + ": " + geometry.error());
  return Result<LoadedTable>::ok(makeLoadedTable(std::move(*spec), std::move(*geometry)));
}

Result<table::TableGeometry> tableGeometry(const table::TableSpec& spec) {
  std::error_code ec;
  if (spec.collision_mesh.empty() || !std::filesystem::exists(spec.collision_mesh, ec)) {
    return Result<table::TableGeometry>::ok(table::buildTableGeometry(spec));
  }
  return table::loadTableGeometry(spec);
}

Result<std::shared_ptr<const LoadedTable>> loadSharedTable(const std::string& name) {
  using Out = Result<std::shared_ptr<const LoadedTable>>;
  auto loaded = loadTable(name);
  if (!loaded) return Out::fail(loaded.error());
  return Out::ok(std::make_shared<const LoadedTable>(std::move(*loaded)));
}

int pocketIndex(const LoadedTable& table, const std::string& name) {
  for (std::size_t i = 0; i < table.pockets.size(); ++i) {
    if (table.pockets[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace pool::game
