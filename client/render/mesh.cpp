// Mesh upload into vertex arrays and drawing.
#include "client/render/mesh.h"

#include <glad/gl.h>

#include <array>
#include <cstdint>
#include <map>

namespace pool::render {

void createVec3PairArray(unsigned& vao, unsigned& vbo) {
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  const auto stride = static_cast<GLsizei>(6 * sizeof(float));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
}

GpuMesh::GpuMesh(const MeshData& data) : count_(static_cast<int>(data.positions.size())) {
  // Indexed, each distinct vertex once: a software renderer shades a shared vertex once per
  // batch instead of once per triangle.
  std::vector<float> interleaved;
  std::vector<std::uint32_t> indices;
  indices.reserve(data.positions.size());
  std::map<std::array<float, 6>, std::uint32_t> index_of;
  for (std::size_t i = 0; i < data.positions.size(); ++i) {
    const glm::vec3& p = data.positions[i];
    const glm::vec3& n = data.normals[i];
    const std::array<float, 6> vertex{p.x, p.y, p.z, n.x, n.y, n.z};
    const auto [it, added] = index_of.emplace(vertex, static_cast<std::uint32_t>(index_of.size()));
    if (added) interleaved.insert(interleaved.end(), vertex.begin(), vertex.end());
    indices.push_back(it->second);
  }
  createVec3PairArray(vao_, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
               interleaved.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);  // recorded in the vertex array
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
  glDeleteBuffers(1, &ebo_);
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace pool::render
