// Overlay segments: one interleaved position+colour buffer, drawn as GL_LINES without depth test.
#include "client/render/overlay_lines.h"

#include <glad/gl.h>

#include "client/render/mesh.h"
#include "client/render/shaders.h"

namespace pool::render {

OverlayLines::OverlayLines() : program_(shaders::kLineVertex, shaders::kLineFragment) {
  createVec3PairArray(vao_, vbo_);
  glBindVertexArray(0);
}

OverlayLines::~OverlayLines() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void OverlayLines::set(const std::vector<OverlayLine>& lines) {
  std::vector<float> data;
  data.reserve(lines.size() * 12);
  for (const OverlayLine& line : lines) {
    for (const glm::vec3& p : {line.a, line.b}) {
      data.insert(data.end(), {p.x, p.y, p.z, line.colour.r, line.colour.g, line.colour.b});
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_DYNAMIC_DRAW);
  vertices_ = static_cast<int>(lines.size() * 2);
}

void OverlayLines::draw(const glm::mat4& view_projection) const {
  if (vertices_ == 0) return;
  glDisable(GL_DEPTH_TEST);
  program_.use();
  program_.set("uViewProj", view_projection);
  glBindVertexArray(vao_);
  glLineWidth(1.0f);
  glDrawArrays(GL_LINES, 0, vertices_);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace pool::render
