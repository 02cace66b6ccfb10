// The Magic Eight Ball room: a giant 8-ball on a wooden stool under two spotlights, its answer
// window (a blue icosahedron face in a dark round window) turned toward the viewer.
#pragma once

#include <memory>
#include <string>

#include "client/render/renderer.h"
#include "client/render/scene_shading.h"

namespace pool::render {

/// GPU resources of the room; needs a current OpenGL 3.3 core context. Throws std::runtime_error
/// when a shader or the font cannot be loaded.
class EightBallRoom {
 public:
  EightBallRoom();
  ~EightBallRoom();
  EightBallRoom(const EightBallRoom&) = delete;
  EightBallRoom& operator=(const EightBallRoom&) = delete;

  /// Where the viewer stands: in front of the ball, a little above it.
  static Camera defaultCamera();
  /// The ball's centre and radius (room frame, +z up, m).
  static glm::vec3 ballCentre();
  static float ballRadius();
  /// Centre of the answer window as seen from `camera` (on the ball's surface, facing it).
  static glm::vec3 windowCentre(const Camera& camera);

  void setOptions(const RenderOptions& options) { options_ = options; }
  /// Clears and draws the room into the bound framebuffer, `answer` on the triangle (wrapped).
  void draw(const Camera& camera, int width, int height, const std::string& answer);

 private:
  void drawWindow(const Camera& camera, float aspect, const std::string& answer);

  RenderOptions options_;
  SceneShading shading_;
  GpuMesh sphere_;
  GpuMesh disc_;
  GpuMesh floor_;
  GpuMesh walls_;
  GpuMesh stool_;
  GpuMesh triangle_;
  ShaderProgram decal_;
  TextRasterizer text_;
  GpuTexture answer_texture_;
  std::string shown_;  ///< the answer in answer_texture_
};

}  // namespace pool::render
