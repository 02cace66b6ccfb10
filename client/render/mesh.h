// Triangle meshes: CPU-side builders (table parts, spheres, discs) and their GPU buffers.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "table/table_geometry.h"

namespace pool::render {

/// Unindexed triangles: three consecutive vertices per triangle, one normal per vertex.
struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
};

/// A table mesh part with flat (per-triangle) normals.
MeshData meshFromPart(const pool::table::MeshPart& part);
/// A unit sphere centred on the origin, smooth normals.
MeshData unitSphere(int stacks, int slices);
/// A horizontal disc of radius 1 at z = 0, facing +z.
MeshData unitDisc(int slices);

/// The mesh in a vertex array object (location 0: position, 1: normal).
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
  int count_ = 0;
};

}  // namespace pool::render
