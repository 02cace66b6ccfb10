// Mesh asset import through assimp.
#include "client/render/mesh_asset.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "table/assets.h"

namespace pool::render {

namespace {

glm::vec3 toGlm(const aiVector3D& v) {
  return {v.x, v.y, v.z};
}

void readNode(std::vector<NamedMesh>& out, const aiScene& scene, const aiNode& node) {
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (!mesh.HasNormals()) continue;
    NamedMesh part{node.mName.C_Str(), {}};
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

Result<std::vector<NamedMesh>> loadMeshFile(const std::string& path) {
  using R = Result<std::vector<NamedMesh>>;
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    return R::fail("mesh: " + path + ": " + importer.GetErrorString());
  }
  std::vector<NamedMesh> parts;
  readNode(parts, *scene, *scene->mRootNode);
  if (parts.empty()) return R::fail("mesh: " + path + ": no parts with normals");
  return R::ok(std::move(parts));
}

Result<std::vector<NamedMesh>> loadMeshAsset(const std::string& relative) {
  const auto path = pool::table::findAsset(relative);
  if (!path) return Result<std::vector<NamedMesh>>::fail("mesh: assets/" + relative + " not found");
  return loadMeshFile(path->string());
}

}  // namespace pool::render
