// A mesh asset (an OBJ in assets/) read through assimp as named parts.
#pragma once

#include <string>
#include <vector>

#include "client/render/mesh.h"
#include "core/result.h"

namespace pool::render {

/// Reads the OBJ at `path` (assimp; triangles, normals as written), one part per object in file
/// order. Fails with a one-line reason, also when no object has normals.
Result<std::vector<NamedMesh>> loadMeshFile(const std::string& path);

/// Reads `relative` (e.g. "cue/cue.obj") from the assets folder.
Result<std::vector<NamedMesh>> loadMeshAsset(const std::string& relative);

}  // namespace pool::render
