// Writes the screenshot sidecar with nlohmann-json.
#include "client/render/screenshot_info.h"

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "client/render/lamps.h"

namespace pool::render {

namespace {

using nlohmann::json;

json vec(glm::vec3 v) {
  return json::array({v.x, v.y, v.z});
}

json matrix(const glm::mat4& m) {
  json out = json::array();
  const float* values = glm::value_ptr(m);
  for (int i = 0; i < 16; ++i) out.push_back(values[i]);
  return out;
}

/// The image size and the camera, which every sidecar starts with.
json frameJson(const Camera& camera, int width, int height) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return json{{"width", width},
              {"height", height},
              {"camera",
               {{"eye", vec(camera.eye)},
                {"target", vec(camera.target)},
                {"up", vec(camera.up)},
                {"fov_y_deg", camera.fov_y_deg},
                {"view", matrix(viewMatrix(camera))},
                {"projection", matrix(projectionMatrix(camera, aspect))}}}};
}

}  // namespace

nlohmann::json pointJson(const Camera& camera, int width, int height, glm::vec3 p) {
  const glm::vec3 px = projectToPixels(camera, width, height, p);
  const bool behind = px.z < 0.0f;  // projectToPixels' mark for a point behind the eye
  const bool on_screen = !behind && px.x >= 0.0f && px.x <= static_cast<float>(width) &&
                         px.y >= 0.0f && px.y <= static_cast<float>(height) && px.z <= 1.0f;
  return json{{"pos", vec(p)},
              {"px", behind ? json(nullptr) : json::array({px.x, px.y})},
              {"on_screen", on_screen}};
}

std::string eightBallInfoJson(const Camera& camera, int width, int height, glm::vec3 centre,
                              float radius, glm::vec3 window, const std::string& answer) {
  json info = frameJson(camera, width, height);
  info["eight_ball"] = {{"centre", pointJson(camera, width, height, centre)},
                        {"radius", radius},
                        {"window", pointJson(camera, width, height, window)},
                        {"answer", answer}};
  return info.dump(2) + "\n";
}

std::string screenshotInfoJson(const Camera& camera, int width, int height,
                               const Renderer& renderer, double ball_radius,
                               const pool::table::TableGeometry& geometry) {
  const auto point = [&](glm::vec3 p) { return pointJson(camera, width, height, p); };
  json info = frameJson(camera, width, height);
  info.update(json{{"ball_radius", ball_radius},
                   {"balls", json::array()},
                   {"lamps", json::array()},
                   {"diamonds", json::array()}});
  for (const SceneBall& b : renderer.drawnBalls()) {
    info["balls"].push_back({{"id", b.id},
                             {"pos", json::array({b.pos.x(), b.pos.y(), b.pos.z()})},
                             {"pocketed", b.pocketed}});
  }
  if (const auto& cue = renderer.cue()) {
    info["cue"] = {{"tip", point(cue->tip)},
                   {"butt", point(cue->butt)},
                   {"drawn_elevation_deg", glm::degrees(cue->drawn_elevation)}};
  }
  if (const auto& ghost = renderer.ghost()) info["ghost"] = point(*ghost);
  const std::vector<glm::vec3> keep_clear = renderer.keepClear();
  for (const glm::vec3& light : lampPositions(geometry)) {
    info["lamps"].push_back({{"light", point(light)},
                             {"pool", point(glm::vec3(light.x, light.y, 0.0f))},
                             {"opacity", lampOpacity(camera, width, height, light, keep_clear)}});
  }
  for (const glm::vec3& d : renderer.diamonds()) info["diamonds"].push_back(point(d));
  return info.dump(2) + "\n";
}

}  // namespace pool::render
