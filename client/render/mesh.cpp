// Mesh upload into vertex arrays and drawing.
#include <glad/gl.h>

#include "client/render/mesh.h"

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
  std::vector<float> interleaved;
  interleaved.reserve(data.positions.size() * 6);
  for (std::size_t i = 0; i < data.positions.size(); ++i) {
    const glm::vec3& p = data.positions[i];
    const glm::vec3& n = data.normals[i];
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
  }
  createVec3PairArray(vao_, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
               interleaved.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, count_);
}

}  // namespace pool::render
