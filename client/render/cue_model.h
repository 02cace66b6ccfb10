// The cue's mesh (assets/cue/cue.obj, written by pool-cuegen) read through assimp, its parts'
// looks, and their GPU buffers.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "client/render/mesh.h"
#include "core/result.h"

namespace pool::render {

/// One named part of the cue mesh (tip, ferrule, shaft, joint, forearm, wrap, sleeve, bumper), in
/// the cue's frame: tip at the origin, axis along +x toward the butt, metres.
using CueMeshPart = NamedMesh;

/// Reads assets/cue/cue.obj from the assets folder (mesh_asset.h).
Result<std::vector<CueMeshPart>> loadCueAsset();

/// How a cue part looks: its colour and the scene shader's material (shaders::Material).
struct CuePartLook {
  glm::vec3 colour;
  int material = 0;
  float specular = 0.0f;  ///< varnish highlight strength
};
CuePartLook cuePartLook(const std::string& part_name);

/// The parts on the GPU; needs a current OpenGL 3.3 core context.
class CueModel {
 public:
  explicit CueModel(const std::vector<CueMeshPart>& parts);

  struct Part {
    std::unique_ptr<GpuMesh> mesh;
    CuePartLook look;
  };
  const std::vector<Part>& parts() const { return parts_; }

 private:
  std::vector<Part> parts_;
};

}  // namespace pool::render
