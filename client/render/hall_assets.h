// The hall's generated assets: the room's OBJ and each table's dressing OBJ as the generator
// writes them, and the dressing as the renderer reads it.
#pragma once

#include <string>
#include <vector>

#include "client/render/mesh.h"
#include "core/result.h"
#include "table/table_geometry.h"

namespace pool::render {

/// assets/hall/room.obj's text.
Result<std::string> roomObj();
/// assets/hall/<table>.obj's text for the table spec `table` (a name or a path).
Result<std::string> dressingObj(const std::string& table);

/// The room's parts from assets/hall/room.obj.
Result<std::vector<NamedMesh>> loadRoom();
/// The dressing of `geometry` from assets/hall/<its name>.obj, or built from the geometry when
/// that table has no file (a spec of the user's own).
std::vector<NamedMesh> loadDressing(const pool::table::TableGeometry& geometry,
                                    float cushion_width);

}  // namespace pool::render
