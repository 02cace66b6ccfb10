// Scene drawing: felt and wooden table parts, pocket holes, numbered balls turned by their
// orientation, the lamps and the trough of pocketed balls, then the overlay lines on top.
#include "client/render/renderer.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "client/render/lamps.h"
#include "client/render/palette.h"
#include "client/render/shaders.h"

namespace pool::render {

namespace {

constexpr float kSurfaceLift = 0.0005f;  // pocket discs sit this far above the slate, m
constexpr glm::vec3 kBackground(0.10f, 0.10f, 0.12f);
constexpr float kTroughLight = 0.75f;  // share of the albedo lit in the trough

glm::vec3 toGlm(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

}  // namespace

Camera overviewCamera(const pool::table::TableGeometry& geometry, float aspect) {
  const float half_length = static_cast<float>(geometry.length) * 0.5f + 0.25f;
  const float fov = 40.0f;
  const float half_fov_x = std::atan(std::tan(glm::radians(fov) * 0.5f) * aspect);
  const float distance = half_length / std::tan(half_fov_x) * 1.3f;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, -0.55f, 1.0f));
  return {glm::vec3(0.0f, 0.0f, 0.0f) + direction * distance, glm::vec3(0.0f, 0.0f, -0.05f), fov};
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
  const glm::mat4 view = glm::lookAt(camera.eye, camera.target, glm::vec3(0.0f, 0.0f, 1.0f));
  const glm::mat4 proj = glm::perspective(glm::radians(camera.fov_y_deg), aspect, 0.05f, 50.0f);
  return proj * view;
}

glm::vec3 projectToPixels(const Camera& camera, int width, int height, glm::vec3 p) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::vec4 clip = viewProjection(camera, aspect) * glm::vec4(p, 1.0f);
  if (clip.w <= 0.0f) return {0.0f, 0.0f, -1.0f};
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width),
          (0.5f - ndc.y * 0.5f) * static_cast<float>(height), ndc.z * 0.5f + 0.5f};
}

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      trough_(scene.geometry, scene.ball_radius),
      sphere_(unitSphere(16, 24)),
      disc_(unitDisc(40)),
      shade_(lampShade()) {
  for (const auto& part : scene_.geometry.parts) {
    if (part.triangles.empty()) continue;
    const PartLook look = partLook(part.name);
    parts_.push_back({std::make_unique<GpuMesh>(meshFromPart(part)), look.colour, look.material});
  }
  parts_.push_back({std::make_unique<GpuMesh>(trough_.mesh()), woodColour(), shaders::kWood});
  trough_.update(scene_.balls);
}

void Renderer::setBalls(std::vector<SceneBall> balls) {
  scene_.balls = std::move(balls);
  trough_.update(scene_.balls);
}

void Renderer::setOverlay(std::vector<OverlayLine> lines) {
  overlay_.set(lines);
}

std::vector<SceneBall> Renderer::drawnBalls() const {
  std::vector<SceneBall> drawn = scene_.balls;
  for (SceneBall& ball : drawn) {
    if (!ball.pocketed) continue;
    // Laid out for display, like a rack: number toward the viewer.
    if (const auto slot = trough_.slotOf(ball.id)) {
      ball.pos = trough_.slot(*slot);
      ball.orientation = numberTowardViewer();
    }
  }
  return drawn;
}

void Renderer::drawHoles() const {
  for (const auto& hole : scene_.geometry.holes) {
    const glm::vec3 centre(static_cast<float>(hole.centre.x()), static_cast<float>(hole.centre.y()),
                           kSurfaceLift);
    const auto r = static_cast<float>(hole.radius);
    const glm::mat4 model =
        glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(r, r, 1.0f));
    shading_.draw(disc_, model, holeColour(), shaders::kPlain, 0.0f);
  }
}

void Renderer::drawBalls() const {
  const auto r = static_cast<float>(scene_.ball_radius);
  for (const SceneBall& ball : drawnBalls()) {
    const Eigen::Quaterniond& q = ball.orientation;
    const glm::quat rotation(static_cast<float>(q.w()), static_cast<float>(q.x()),
                             static_cast<float>(q.y()), static_cast<float>(q.z()));
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), toGlm(ball.pos)) *
                            glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), glm::vec3(r));
    // The trough is lit by its own strip light under the rail, out of the lamps' cones.
    if (ball.pocketed) shading_.setAmbient(kTroughLight);
    shading_.drawBall(sphere_, model, ball.id);
    if (ball.pocketed) shading_.setAmbient(SceneShading::kAmbient);
  }
}

void Renderer::drawLamps() const {
  for (const glm::vec3& light : lampPositions(scene_.geometry)) {
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), light);
    shading_.draw(shade_, at, shadeColour(), shaders::kEmissive, 0.0f);
    const glm::mat4 bulb = glm::scale(at, glm::vec3(kBulbRadius, kBulbRadius, 1.0f));
    shading_.draw(disc_, bulb, bulbColour(), shaders::kEmissive, 0.0f);
  }
}

void Renderer::draw(const Camera& camera, int width, int height) const {
  const auto lamps = lampPositions(scene_.geometry);
  shading_.beginFrame(camera, width, height, kBackground, {lamps, kSpotInnerDeg, kSpotOuterDeg},
                      options_);
  for (const Part& part : parts_) {
    shading_.draw(*part.mesh, glm::mat4(1.0f), part.colour, part.material, 0.05f);
  }
  drawHoles();
  drawBalls();
  drawLamps();
  shading_.endFrame();
  overlay_.draw(viewProjection(camera, static_cast<float>(width) / static_cast<float>(height)));
}

}  // namespace pool::render
