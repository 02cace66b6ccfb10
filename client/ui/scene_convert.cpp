// Conversions from the client model to the renderer's types.
#include "client/ui/scene_convert.h"

#include "client/render/lamps.h"

namespace pool::ui {
namespace {

glm::vec3 vec(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

}  // namespace

std::vector<render::SceneBall> sceneBalls(const std::vector<physics::Ball>& balls) {
  std::vector<render::SceneBall> out;
  out.reserve(balls.size());
  for (const auto& b : balls) {
    out.push_back({b.id, b.pos, b.orient, !physics::onTable(b.state)});
  }
  return out;
}

render::Camera cameraOf(const app::ViewPoint& view) {
  return {vec(view.eye), vec(view.target), static_cast<float>(view.fov_y_deg)};
}

app::CameraRig cameraRigFor(const table::TableGeometry& geometry, double aspect) {
  app::CameraRig rig(geometry.length, geometry.width, aspect);
  std::vector<Eigen::Vector3d> lights;
  for (const glm::vec3& p : render::lampPositions(geometry)) lights.emplace_back(p.x, p.y, p.z);
  rig.setLights(std::move(lights));
  return rig;
}

std::vector<render::OverlayLine> overlayLines(const std::vector<app::OverlaySegment>& segments) {
  std::vector<render::OverlayLine> out;
  out.reserve(segments.size());
  for (const auto& s : segments) out.push_back({vec(s.a), vec(s.b), vec(s.colour)});
  return out;
}

}  // namespace pool::ui
