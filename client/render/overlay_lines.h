// Overlay segments (aim line, cue, direction vectors): unlit coloured lines drawn over the scene.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "client/render/shader.h"

namespace pool::render {

/// A coloured segment drawn over the scene, unlit (aim line, cue, direction vectors).
struct OverlayLine {
  glm::vec3 a;
  glm::vec3 b;
  glm::vec3 colour;
};

/// The segments in a dynamic vertex buffer; needs a current OpenGL 3.3 core context.
class OverlayLines {
 public:
  OverlayLines();
  ~OverlayLines();
  OverlayLines(const OverlayLines&) = delete;
  OverlayLines& operator=(const OverlayLines&) = delete;

  /// Replaces the segments (uploaded now).
  void set(const std::vector<OverlayLine>& lines);
  /// Draws them on top of whatever is in the framebuffer (no depth test).
  void draw(const glm::mat4& view_projection) const;

 private:
  ShaderProgram program_;
  unsigned vao_ = 0;
  unsigned vbo_ = 0;
  int vertices_ = 0;
};

}  // namespace pool::render
