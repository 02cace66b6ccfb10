// The hall as the balls' clear coat mirrors it: a cube map of the room, the table and the lamps
// seen from over the table's centre, captured once with the scene's own drawing.
#pragma once

#include <functional>
#include <glm/glm.hpp>

#include "client/render/camera.h"

namespace pool::render {

/// A mipmapped RGBA8 cube texture; needs a current OpenGL 3.3 core context.
class EnvironmentMap {
 public:
  /// Texels a side of each face.
  static constexpr int kSize = 128;

  EnvironmentMap();
  ~EnvironmentMap();
  EnvironmentMap(const EnvironmentMap&) = delete;
  EnvironmentMap& operator=(const EnvironmentMap&) = delete;

  /// The camera of cube face `face` (0–5: +x, −x, +y, −y, +z, −z) at `centre`: 90° square, its
  /// image the way OpenGL's cube-map lookup reads the face.
  static Camera faceCamera(glm::vec3 centre, int face);

  /// Draws each face from `centre` with `draw` (given the face's camera, into the bound face at
  /// kSize × kSize), then the mipmaps; the framebuffer and viewport bound before are bound again.
  void capture(glm::vec3 centre, const std::function<void(const Camera&)>& draw);
  bool captured() const { return captured_; }
  /// Binds the cube texture to texture unit `unit`.
  void bind(int unit) const;

 private:
  unsigned texture_ = 0, fbo_ = 0, depth_ = 0;
  bool captured_ = false;
};

}  // namespace pool::render
