// Generated hall assets: written by pool-hallgen, read back through assimp.
#include "client/render/hall_assets.h"

#include "client/render/hall_room.h"
#include "client/render/mesh_asset.h"
#include "client/render/obj_text.h"
#include "client/render/table_dressing.h"
#include "table/assets.h"

namespace pool::render {

Result<std::string> roomObj() {
  return Result<std::string>::ok(
      objText(hallRoom(), {"The pool hall round the table (table frame, metres, z up).",
                           "Written by pool-hallgen room; do not edit."}));
}

Result<std::string> dressingObj(const std::string& table) {
  const auto spec = pool::table::loadTableSpec(table);
  if (!spec) return Result<std::string>::fail(spec.error());
  const auto geometry = pool::table::buildTableGeometry(*spec);
  return Result<std::string>::ok(
      objText(tableDressing(geometry, static_cast<float>(spec->cushion_width)),
              {"The dressing of table " + spec->name + " (table frame, metres, z up).",
               "Written by pool-hallgen " + spec->name + "; do not edit."}));
}

Result<std::vector<NamedMesh>> loadRoom() {
  return loadMeshAsset("hall/room.obj");
}

std::vector<NamedMesh> loadDressing(const pool::table::TableGeometry& geometry,
                                    float cushion_width) {
  if (!geometry.name.empty() && geometry.name.find('/') == std::string::npos &&
      pool::table::findAsset("hall/" + geometry.name + ".obj")) {
    if (auto parts = loadMeshAsset("hall/" + geometry.name + ".obj")) return std::move(*parts);
  }
  return tableDressing(geometry, cushion_width);
}

}  // namespace pool::render
