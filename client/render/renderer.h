// Draws a Scene (table parts, pocket holes, balls) with two spotlights and Blinn-Phong shading.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "client/render/mesh.h"
#include "client/render/scene.h"
#include "client/render/shader.h"

namespace pool::render {

/// A perspective camera (table frame, +z up).
struct Camera {
  glm::vec3 eye;
  glm::vec3 target;
  float fov_y_deg = 45.0f;
};

/// A camera above the long side that frames the whole table for the given aspect (w / h).
Camera overviewCamera(const pool::table::TableGeometry& geometry, float aspect);

/// GPU resources of one scene; needs a current OpenGL 3.3 core context.
class Renderer {
 public:
  explicit Renderer(const Scene& scene);

  /// Clears and draws the scene into the bound framebuffer of size width × height.
  void draw(const Camera& camera, int width, int height) const;

 private:
  struct Part {
    std::unique_ptr<GpuMesh> mesh;
    glm::vec3 colour;
  };
  void setFrameUniforms(const Camera& camera, float aspect) const;
  void drawMesh(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, bool striped,
                float specular) const;
  void drawBalls() const;
  void drawHoles() const;

  Scene scene_;
  ShaderProgram program_;
  std::vector<Part> parts_;
  GpuMesh sphere_;
  GpuMesh disc_;
};

}  // namespace pool::render
