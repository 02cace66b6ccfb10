// Draws shadow ellipses on the slate: soft-edged quads that darken the felt under them.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "client/render/ball_shadows.h"
#include "client/render/shader.h"

namespace pool::render {

/// The blobs in a dynamic vertex buffer; needs a current OpenGL 3.3 core context.
class ShadowLayer {
 public:
  ShadowLayer();
  ~ShadowLayer();
  ShadowLayer(const ShadowLayer&) = delete;
  ShadowLayer& operator=(const ShadowLayer&) = delete;

  /// Replaces the blobs (uploaded now).
  void set(const std::vector<ShadowBlob>& blobs);
  /// Multiplies the framebuffer under each blob by (1 − darkness · edge falloff), depth-tested
  /// against what is drawn, without writing depth.
  void draw(const glm::mat4& view_projection) const;
  /// The half-extents of the playing surface and of the table's outer edge: raised shadows
  /// (on the rails) show only between them.
  void setTableExtent(glm::vec2 playing, glm::vec2 edge) {
    playing_ = playing;
    edge_ = edge;
  }

 private:
  ShaderProgram program_;
  unsigned vao_ = 0;
  unsigned vbo_ = 0;
  int vertices_ = 0;
  glm::vec2 playing_{0.0f};
  glm::vec2 edge_{0.0f};
};

}  // namespace pool::render
