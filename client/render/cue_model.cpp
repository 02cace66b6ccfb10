// Cue mesh import (assimp) and part looks.
#include "client/render/cue_model.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "client/render/shaders.h"
#include "table/assets.h"

namespace pool::render {

namespace {

glm::vec3 toGlm(const aiVector3D& v) {
  return {v.x, v.y, v.z};
}

void readNode(std::vector<CueMeshPart>& out, const aiScene& scene, const aiNode& node) {
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (!mesh.HasNormals()) continue;
    CueMeshPart part{node.mName.C_Str(), {}};
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k) {
        part.mesh.positions.push_back(toGlm(mesh.mVertices[face.mIndices[k]]));
        part.mesh.normals.push_back(toGlm(mesh.mNormals[face.mIndices[k]]));
      }
    }
    out.push_back(std::move(part));
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) readNode(out, scene, *node.mChildren[i]);
}

}  // namespace

Result<std::vector<CueMeshPart>> loadCueMesh(const std::string& path) {
  using R = Result<std::vector<CueMeshPart>>;
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    return R::fail("cue mesh: " + path + ": " + importer.GetErrorString());
  }
  std::vector<CueMeshPart> parts;
  readNode(parts, *scene, *scene->mRootNode);
  if (parts.empty()) return R::fail("cue mesh: " + path + ": no parts with normals");
  return R::ok(std::move(parts));
}

Result<std::vector<CueMeshPart>> loadCueAsset() {
  const auto path = pool::table::findAsset("cue/cue.obj");
  if (!path)
    return Result<std::vector<CueMeshPart>>::fail("cue mesh: assets/cue/cue.obj not found");
  return loadCueMesh(path->string());
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
