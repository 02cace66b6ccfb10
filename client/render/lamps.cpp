// Lamp placement, light, visibility and shade geometry.
#include "client/render/lamps.h"

#include <algorithm>
#include <cmath>

namespace pool::render {

namespace {

constexpr float kShadeHeight = 0.17f;     // m from rim to top
constexpr float kShadeTopRadius = 0.07f;  // m
constexpr float kEyeClearance = 0.15f;    // m between the eye and the shade's sphere: gone
constexpr float kEyeFade = 0.25f;         // m farther over which it comes back
constexpr float kPlanSine = 0.94f;        // sin 70°: a view looking down steeper is a plan

}  // namespace

std::array<glm::vec3, 2> lampPositions(const pool::table::TableGeometry& geometry) {
  const float x = static_cast<float>(geometry.length) * 0.25f;
  return {glm::vec3(-x, 0.0f, kLampHeight), glm::vec3(x, 0.0f, kLampHeight)};
}

float lampLight(glm::vec3 lamp, glm::vec3 point, glm::vec3 normal) {
  const glm::vec3 to_lamp = lamp - point;
  const float distance2 = glm::dot(to_lamp, to_lamp);
  if (distance2 <= 0.0f) return 0.0f;
  const glm::vec3 l = to_lamp / std::sqrt(distance2);
  const float c_in = std::cos(glm::radians(kSpotInnerDeg));
  const float c_out = std::cos(glm::radians(kSpotOuterDeg));
  const float t = std::clamp((l.z - c_out) / (c_in - c_out), 0.0f, 1.0f);
  const float cone = t * t * (3.0f - 2.0f * t);
  const float falloff = std::min(lamp.z * lamp.z / distance2, 1.3f);
  return kLampGain * cone * std::max(glm::dot(normal, l), 0.0f) * falloff;
}

std::optional<ShadeDisc> shadeDisc(const Camera& camera, int width, int height, glm::vec3 lamp) {
  const glm::vec3 centre = lamp + glm::vec3(0.0f, 0.0f, kShadeHeight * 0.5f - kShadeRimBelow);
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  const float depth = glm::dot(centre - camera.eye, forward);
  const float distance = glm::length(centre - camera.eye);
  const float diagonal = std::hypot(static_cast<float>(width), static_cast<float>(height));
  if (distance <= kShadeBound) {  // the eye is inside the shade's sphere
    return ShadeDisc{{0.5f * static_cast<float>(width), 0.5f * static_cast<float>(height)},
                     2.0f * diagonal,
                     distance};
  }
  if (depth <= 0.0f) return std::nullopt;
  const glm::vec3 px = projectToPixels(camera, width, height, centre);
  // The sphere's angular radius, as a radius on the image plane (at depth 1), in pixels.
  const float half = std::asin(kShadeBound / distance);
  const float focal =
      static_cast<float>(height) * 0.5f / std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
  const float radius = focal * std::tan(half) / std::max(depth / distance, 0.05f);
  return ShadeDisc{{px.x, px.y}, std::min(radius, 2.0f * diagonal), distance};
}

float lampOpacity(const Camera& camera, int width, int height, glm::vec3 lamp,
                  std::span<const glm::vec3> keep_clear) {
  // A view straight down from over the lamps (the overhead, the top scene) is a plan of the
  // table: nothing hangs between.
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  if (forward.z < -kPlanSine && camera.eye.z > lamp.z) return 0.0f;
  const auto disc = shadeDisc(camera, width, height, lamp);
  if (!disc) return 1.0f;  // behind the eye: nothing to hide
  float opacity = std::clamp((disc->distance - kShadeBound - kEyeClearance) / kEyeFade, 0.0f, 1.0f);
  for (const glm::vec3& point : keep_clear) {
    // A point nearer the eye than the shade is drawn over it.
    if (glm::length(point - camera.eye) < disc->distance - kShadeBound) continue;
    const glm::vec3 px = projectToPixels(camera, width, height, point);
    if (px.z < 0.0f) continue;
    const float gap = glm::length(glm::vec2(px.x, px.y) - disc->centre) - disc->radius;
    const float fade = std::clamp((gap - kClearMargin) / (kClearFade * disc->radius), 0.0f, 1.0f);
    opacity = std::min(opacity, fade);
  }
  return opacity;
}

MeshData lampShade() {
  MeshData shade = openFrustum(kShadeRadius, kShadeTopRadius, kShadeHeight, 48);
  MeshData top = unitDisc(24);
  for (auto& p : top.positions) p = p * glm::vec3(kShadeTopRadius, kShadeTopRadius, 1.0f);
  for (auto& p : top.positions) p.z += kShadeHeight;
  append(shade, top);
  MeshData cord = openFrustum(0.006f, 0.006f, 2.0f, 8);
  for (auto& p : cord.positions) p.z += kShadeHeight;
  append(shade, cord);
  for (auto& p : shade.positions) p.z -= kShadeRimBelow;
  return shade;
}

}  // namespace pool::render
