// Writes the screenshot sidecar with nlohmann-json.
#include "client/render/screenshot_info.h"

#include <nlohmann/json.hpp>

namespace pool::render {

std::string screenshotInfoJson(const Camera& camera, int width, int height, double ball_radius,
                               const std::vector<SceneBall>& balls) {
  using nlohmann::json;
  const auto vec = [](glm::vec3 v) { return json::array({v.x, v.y, v.z}); };
  json info{
      {"width", width},
      {"height", height},
      {"ball_radius", ball_radius},
      {"camera",
       {{"eye", vec(camera.eye)}, {"target", vec(camera.target)}, {"fov_y_deg", camera.fov_y_deg}}},
      {"balls", json::array()}};
  for (const SceneBall& b : balls) {
    info["balls"].push_back({{"id", b.id},
                             {"pos", json::array({b.pos.x(), b.pos.y(), b.pos.z()})},
                             {"pocketed", b.pocketed}});
  }
  return info.dump(2) + "\n";
}

}  // namespace pool::render
