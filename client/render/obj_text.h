// Named meshes written as a Wavefront OBJ (the generated assets' format).
#pragma once

#include <string>
#include <vector>

#include "client/render/mesh.h"

namespace pool::render {

/// `parts` as an OBJ: `comment` as its header lines (each prefixed "# "), then one `o` object per
/// part, its triangles as `f v//vn` over shared, deduplicated `v` and `vn` lines (positions to
/// 1 µm, normals to 1e-4). Byte-identical for the same parts.
std::string objText(const std::vector<NamedMesh>& parts, const std::vector<std::string>& comment);

}  // namespace pool::render
