// Camera matrices and projection to pixels.
#include "client/render/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace pool::render {

Camera overviewCamera(const pool::table::TableGeometry& geometry, float aspect) {
  const float half_length = static_cast<float>(geometry.length) * 0.5f + 0.25f;
  const float fov = 40.0f;
  const float half_fov_x = std::atan(std::tan(glm::radians(fov) * 0.5f) * aspect);
  const float distance = half_length / std::tan(half_fov_x) * 1.3f;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, -0.55f, 1.0f));
  return {glm::vec3(0.0f, 0.0f, 0.0f) + direction * distance, glm::vec3(0.0f, 0.0f, -0.05f), fov};
}

Camera topCamera(const pool::table::TableGeometry& geometry, float aspect) {
  const float fov = 20.0f;  // narrow, from high up: close to a plan of the table
  const float half_y = std::tan(glm::radians(fov) * 0.5f);
  const float half_x = half_y * aspect;
  const float margin = 0.2f;  // m beyond the nose lines: the rails
  const float along = (static_cast<float>(geometry.length) * 0.5f + margin) / half_x;
  const float across = (static_cast<float>(geometry.width) * 0.5f + margin) / half_y;
  const float height = std::max(along, across);
  return {glm::vec3(0.0f, 0.0f, height), glm::vec3(0.0f), fov, glm::vec3(0.0f, 1.0f, 0.0f)};
}

glm::mat4 viewMatrix(const Camera& camera) {
  return glm::lookAt(camera.eye, camera.target, camera.up);
}

glm::mat4 projectionMatrix(const Camera& camera, float aspect) {
  return glm::perspective(glm::radians(camera.fov_y_deg), aspect, kNearPlane, kFarPlane);
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
  return projectionMatrix(camera, aspect) * viewMatrix(camera);
}

glm::vec3 projectToPixels(const Camera& camera, int width, int height, glm::vec3 p) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::vec4 clip = viewProjection(camera, aspect) * glm::vec4(p, 1.0f);
  if (clip.w <= 0.0f) return {0.0f, 0.0f, -1.0f};
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width),
          (0.5f - ndc.y * 0.5f) * static_cast<float>(height), ndc.z * 0.5f + 0.5f};
}

}  // namespace pool::render
