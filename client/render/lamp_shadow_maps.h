// Each lamp's shadow map: the depth of what its light first meets, seen from the light straight
// down through its cone, which the high preset's shader compares against (soft edges by a
// percentage-closer filter).
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "client/render/mesh.h"
#include "client/render/shader.h"

namespace pool::render {

/// Two depth textures and their light matrices; needs a current OpenGL 3.3 core context.
class LampShadowMaps {
 public:
  /// Texels a side of each map.
  static constexpr int kSize = 1024;
  /// The maps' frustum: this half-angle round straight down (past the widest cone the lamps
  /// light), from kNear to kFar below the light, m.
  static constexpr float kHalfAngleDeg = 55.0f;
  static constexpr float kNear = 0.1f;
  static constexpr float kFar = 3.0f;

  LampShadowMaps();
  ~LampShadowMaps();
  LampShadowMaps(const LampShadowMaps&) = delete;
  LampShadowMaps& operator=(const LampShadowMaps&) = delete;

  /// The light matrix (table frame → the map's clip space) of a light at `lamp`.
  static glm::mat4 lightMatrix(glm::vec3 lamp);

  /// Starts lamp `index`'s map (cleared) for a light at `lamp`: binds its framebuffer, viewport
  /// and depth program, remembering the framebuffer and viewport bound before.
  void begin(int index, glm::vec3 lamp);
  /// Draws `mesh` placed by `model` into the map begun.
  void caster(const GpuMesh& mesh, const glm::mat4& model) const;
  /// Binds the framebuffer and viewport bound before begin() again.
  void end();

  /// Each lamp's light matrix, as last begun.
  const std::array<glm::mat4, 2>& matrices() const { return matrices_; }
  /// Binds lamp `index`'s map to texture unit `unit` (compared against, linearly filtered).
  void bind(int index, int unit) const;

 private:
  ShaderProgram depth_;
  std::array<unsigned, 2> textures_{};
  unsigned fbo_ = 0;
  std::array<glm::mat4, 2> matrices_{};
  int previous_ = 0;
  std::array<int, 4> viewport_{};
};

}  // namespace pool::render
