// The renderer's perspective camera: its matrices, an overview of the table and where a table
// point lands in the image.
#pragma once

#include <glm/glm.hpp>

#include "table/table_geometry.h"

namespace pool::render {

/// A perspective camera (table frame, +z up).
struct Camera {
  glm::vec3 eye;
  glm::vec3 target;
  float fov_y_deg = 45.0f;
  glm::vec3 up{0.0f, 0.0f, 1.0f};  ///< the image's up direction (not along eye → target)
};

/// Near and far clip planes of every camera, m.
inline constexpr float kNearPlane = 0.05f;
inline constexpr float kFarPlane = 50.0f;

/// A camera above the long side that frames the whole table for the given aspect (w / h).
Camera overviewCamera(const pool::table::TableGeometry& geometry, float aspect);
/// A camera straight above the table's centre, +y up in the image, framing the rails.
Camera topCamera(const pool::table::TableGeometry& geometry, float aspect);
/// The view matrix (table frame → eye frame).
glm::mat4 viewMatrix(const Camera& camera);
/// The projection matrix for the given aspect (w / h).
glm::mat4 projectionMatrix(const Camera& camera, float aspect);
/// The camera's projection × view matrix for the given aspect (w / h).
glm::mat4 viewProjection(const Camera& camera, float aspect);
/// Where table point `p` lands in a width × height image: pixels from the top-left corner, and
/// its depth in [0, 1] as z (z < 0 when the point is behind the camera).
glm::vec3 projectToPixels(const Camera& camera, int width, int height, glm::vec3 p);

}  // namespace pool::render
