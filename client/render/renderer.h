// Draws a Scene (table, pockets, numbered balls, lamps, the pocketed-ball trough) with two
// spotlights and Blinn-Phong shading, then the overlay lines.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "client/render/ball_trough.h"
#include "client/render/mesh.h"
#include "client/render/overlay_lines.h"
#include "client/render/scene.h"
#include "client/render/scene_shading.h"

namespace pool::render {

/// A perspective camera (table frame, +z up).
struct Camera {
  glm::vec3 eye;
  glm::vec3 target;
  float fov_y_deg = 45.0f;
};

/// A camera above the long side that frames the whole table for the given aspect (w / h).
Camera overviewCamera(const pool::table::TableGeometry& geometry, float aspect);
/// The camera's projection × view matrix for the given aspect (w / h).
glm::mat4 viewProjection(const Camera& camera, float aspect);
/// Where table point `p` lands in a width × height image: pixels from the top-left corner, and
/// its depth in [0, 1] as z (z < 0 when the point is behind the camera).
glm::vec3 projectToPixels(const Camera& camera, int width, int height, glm::vec3 p);

/// Switches of the drawing (the client's P, T and L keys).
struct RenderOptions {
  bool wireframe = false;  ///< polygons as lines
  bool textures = true;    ///< ball numbers, felt and wood grain (off: flat colours)
  bool lighting = true;    ///< spotlights (off: unlit colours)
};

/// GPU resources of one scene; needs a current OpenGL 3.3 core context. Throws
/// std::runtime_error when a shader or the font cannot be loaded.
class Renderer {
 public:
  explicit Renderer(const Scene& scene);
  /// Replaces the balls (positions and orientations from the latest snapshot). Pocketed balls
  /// are drawn in the trough in the order they were pocketed.
  void setBalls(std::vector<SceneBall> balls);
  void setOptions(const RenderOptions& options) { options_ = options; }
  const RenderOptions& options() const { return options_; }
  /// Replaces the overlay segments drawn after the scene.
  void setOverlay(std::vector<OverlayLine> lines);

  /// The balls as drawn: pocketed ones moved to their place in the trough, number to the viewer.
  std::vector<SceneBall> drawnBalls() const;
  /// Clears and draws the scene into the bound framebuffer of size width × height.
  void draw(const Camera& camera, int width, int height) const;

 private:
  struct Part {
    std::unique_ptr<GpuMesh> mesh;
    glm::vec3 colour;
    int material;
  };
  void drawBalls() const;
  void drawHoles() const;
  void drawLamps() const;

  Scene scene_;
  RenderOptions options_;
  BallTrough trough_;
  SceneShading shading_;
  std::vector<Part> parts_;
  GpuMesh sphere_;
  GpuMesh disc_;
  GpuMesh shade_;
  OverlayLines overlay_;
};

}  // namespace pool::render
