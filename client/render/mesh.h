// Triangle meshes: CPU-side builders (mesh_data.cpp, no GL) and their GPU buffers (mesh.cpp).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "table/table_geometry.h"

namespace pool::render {

/// Unindexed triangles: three consecutive vertices per triangle, one normal per vertex.
struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
};

/// A mesh with a name (an OBJ object's): a part of the cue, the table or the hall.
struct NamedMesh {
  std::string name;
  MeshData mesh;
};

/// A table mesh part with flat (per-triangle) normals.
MeshData meshFromPart(const pool::table::MeshPart& part);
/// A unit sphere centred on the origin, smooth normals.
MeshData unitSphere(int stacks, int slices);
/// A horizontal disc of radius 1 at z = 0, facing +z.
MeshData unitDisc(int slices);
/// An axis-aligned box between corners `lo` and `hi`, flat normals pointing out.
MeshData box(glm::vec3 lo, glm::vec3 hi);
/// An open frustum around the z axis from z = 0 (radius `bottom`) to z = `height` (radius `top`),
/// normals pointing out.
MeshData openFrustum(float bottom, float top, float height, int slices);
/// Appends the quad a b c d (counter-clockwise seen from its front) as two flat triangles; a
/// degenerate quad adds nothing.
void addQuad(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);
/// `mesh` moved by `model` (normals by its inverse transpose).
MeshData transformed(const MeshData& mesh, const glm::mat4& model);
/// Appends `more` to `mesh`.
void append(MeshData& mesh, const MeshData& more);

/// Makes a vertex array over a new array buffer of interleaved vec3 pairs (attribute 0 the first
/// of each pair, attribute 1 the second), leaving both bound; fill the buffer with glBufferData.
void createVec3PairArray(unsigned& vao, unsigned& vbo);

/// The mesh in a vertex array object (location 0: position, 1: normal), indexed: identical
/// vertices (position and normal) are stored once.
class GpuMesh {
 public:
  explicit GpuMesh(const MeshData& data);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  /// Draws the triangles with the current program.
  void draw() const;

 private:
  unsigned vao_ = 0;
  unsigned vbo_ = 0;
  unsigned ebo_ = 0;
  int count_ = 0;  ///< indices
};

}  // namespace pool::render
