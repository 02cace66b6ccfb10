// Test helper: the camera a screenshot's sidecar reports (its view and projection matrices),
// projecting table points to pixels the way a test needs, independently of the renderer's code.
#pragma once

#include <cmath>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace pool::client::test {

/// The sidecar's camera and image size.
struct ReportedCamera {
  int width = 0;
  int height = 0;
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};

  /// Pixel (from the top-left) of table point `p`; z is the clip w (≤ 0: behind the eye).
  glm::vec3 pixel(glm::vec3 p) const {
    const glm::vec4 clip = projection * view * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f) return {0.0f, 0.0f, clip.w};
    return {(clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width),
            (0.5f - clip.y / clip.w * 0.5f) * static_cast<float>(height), clip.w};
  }
  bool inside(glm::vec3 px, float margin = 2.0f) const {
    const auto w = static_cast<float>(width), h = static_cast<float>(height);
    return px.z > 0.0f && px.x >= margin && px.y >= margin && px.x < w - margin &&
           px.y < h - margin;
  }
  /// Unit vectors of the image's right and up directions in the table frame.
  glm::vec3 right() const { return {view[0][0], view[1][0], view[2][0]}; }
  glm::vec3 up() const { return {view[0][1], view[1][1], view[2][1]}; }
  /// Empty when the camera draws the table as a camera sees it; else why not: a view that is
  /// not a rotation and a translation (a reflection: det −1), or a projection that flips an axis
  /// of the image (a mirror the reported matrices would otherwise carry into every expectation).
  std::string mirrored() const {
    const float det = glm::determinant(glm::mat3(view));
    if (std::abs(det - 1.0f) > 1e-3f)
      return "the view's rotation has determinant " + std::to_string(det);
    if (!(projection[0][0] > 0.0f)) return "the projection flips the image's x";
    if (!(projection[1][1] > 0.0f)) return "the projection flips the image's y";
    return {};
  }
};

inline glm::mat4 matrixOf(const nlohmann::json& values) {
  glm::mat4 m(1.0f);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) m[c][r] = values.at(static_cast<std::size_t>(c * 4 + r));
  }
  return m;
}

/// The sidecar at `path` (throws when missing or malformed).
inline nlohmann::json readInfo(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

inline ReportedCamera reportedCamera(const nlohmann::json& info) {
  ReportedCamera c;
  c.width = info.at("width");
  c.height = info.at("height");
  c.view = matrixOf(info.at("camera").at("view"));
  c.projection = matrixOf(info.at("camera").at("projection"));
  const auto& eye = info.at("camera").at("eye");
  c.eye = {eye[0], eye[1], eye[2]};
  return c;
}

/// Relative luminance of a pixel (0..255).
inline double luminance(const std::array<double, 3>& p) {
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

}  // namespace pool::client::test
