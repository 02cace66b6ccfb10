// Scene drawing: table parts flat-shaded, pocket holes as dark discs, balls as lit spheres.
#include "client/render/renderer.h"

#include <glad/gl.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "client/render/palette.h"
#include "client/render/shaders.h"

namespace pool::render {

namespace {

constexpr float kLightHeight = 1.6f;     // m above the slate
constexpr float kSurfaceLift = 0.0005f;  // pocket discs sit this far above the slate, m

}  // namespace

Camera overviewCamera(const pool::table::TableGeometry& geometry, float aspect) {
  const float half_length = static_cast<float>(geometry.length) * 0.5f + 0.25f;
  const float fov = 40.0f;
  const float half_fov_x = std::atan(std::tan(glm::radians(fov) * 0.5f) * aspect);
  const float distance = half_length / std::tan(half_fov_x) * 1.3f;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, -0.55f, 1.0f));
  return {glm::vec3(0.0f, 0.0f, 0.0f) + direction * distance, glm::vec3(0.0f, 0.0f, -0.05f), fov};
}

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      program_(shaders::kSceneVertex, shaders::kSceneFragment),
      sphere_(unitSphere(24, 32)),
      disc_(unitDisc(40)) {
  for (const auto& part : scene_.geometry.parts) {
    if (part.triangles.empty()) continue;
    parts_.push_back({std::make_unique<GpuMesh>(meshFromPart(part)), partColour(part.name)});
  }
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

void Renderer::setFrameUniforms(const Camera& camera, float aspect) const {
  program_.set("uViewProj", viewProjection(camera, aspect));
  program_.set("uEye", camera.eye);
  const float x = static_cast<float>(scene_.geometry.length) * 0.25f;
  program_.set("uLightPos[0]", glm::vec3(-x, 0.0f, kLightHeight));
  program_.set("uLightPos[1]", glm::vec3(x, 0.0f, kLightHeight));
  program_.set("uCosInner", std::cos(glm::radians(35.0f)));
  program_.set("uCosOuter", std::cos(glm::radians(65.0f)));
}

void Renderer::drawMesh(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, bool striped,
                        float specular) const {
  program_.set("uModel", model);
  program_.set("uNormalMatrix", glm::mat3(glm::transpose(glm::inverse(model))));
  program_.set("uColour", colour);
  program_.set("uStriped", striped ? 1 : 0);
  program_.set("uSpecular", specular);
  mesh.draw();
}

void Renderer::drawHoles() const {
  for (const auto& hole : scene_.geometry.holes) {
    const glm::vec3 centre(static_cast<float>(hole.centre.x()), static_cast<float>(hole.centre.y()),
                           kSurfaceLift);
    const auto r = static_cast<float>(hole.radius);
    const glm::mat4 model =
        glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(r, r, 1.0f));
    drawMesh(disc_, model, holeColour(), false, 0.0f);
  }
}

void Renderer::drawBalls() const {
  const auto r = static_cast<float>(scene_.ball_radius);
  for (const SceneBall& ball : scene_.balls) {
    const glm::vec3 centre(static_cast<float>(ball.pos.x()), static_cast<float>(ball.pos.y()),
                           static_cast<float>(ball.pos.z()));
    const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(r));
    const BallLook look = ballLook(ball.id);
    drawMesh(sphere_, model, look.colour, look.striped, 0.5f);
  }
}

void Renderer::draw(const Camera& camera, int width, int height) const {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(0.10f, 0.10f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  program_.use();
  setFrameUniforms(camera, static_cast<float>(width) / static_cast<float>(height));
  for (const Part& part : parts_) drawMesh(*part.mesh, glm::mat4(1.0f), part.colour, false, 0.05f);
  drawHoles();
  drawBalls();
}

}  // namespace pool::render
