// Cue mesh import (assimp) and part looks.
#include "client/render/cue_model.h"

#include "client/render/mesh_asset.h"
#include "client/render/shaders.h"

namespace pool::render {

Result<std::vector<CueMeshPart>> loadCueAsset() {
  return loadMeshAsset("cue/cue.obj");
}

CuePartLook cuePartLook(const std::string& name) {
  if (name == "tip") return {{0.16f, 0.34f, 0.62f}, shaders::kPlain, 0.0f};  // blue chalk
  if (name == "ferrule") return {{0.93f, 0.92f, 0.86f}, shaders::kCue, 0.5f};
  if (name == "shaft") return {{0.86f, 0.69f, 0.45f}, shaders::kCue, 0.35f};  // maple
  if (name == "joint") return {{0.80f, 0.66f, 0.30f}, shaders::kCue, 0.8f};   // brass
  if (name == "forearm" || name == "sleeve") {
    return {{0.36f, 0.11f, 0.05f}, shaders::kCue, 0.45f};  // rosewood
  }
  if (name == "wrap") return {{0.07f, 0.07f, 0.08f}, shaders::kPlain, 0.0f};  // linen
  return {{0.03f, 0.03f, 0.03f}, shaders::kCue, 0.2f};                        // bumper
}

CueModel::CueModel(const std::vector<CueMeshPart>& parts) {
  for (const CueMeshPart& part : parts) {
    parts_.push_back({std::make_unique<GpuMesh>(part.mesh), cuePartLook(part.name)});
  }
}

}  // namespace pool::render
