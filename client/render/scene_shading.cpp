// Per-material programs (the full preset's and the high one's) and their frame uniforms.
#include "client/render/scene_shading.h"

#include <glad/gl.h>

#include <cmath>
#include <string>

#include "client/render/lamp_shadow_maps.h"
#include "client/render/lamps.h"
#include "client/render/noise_texture.h"
#include "client/render/number_atlas.h"
#include "client/render/palette.h"
#include "client/render/renderer.h"
#include "client/render/shaders.h"

namespace pool::render {

namespace {

constexpr int kNumbersUnit = 0;  // texture unit of the number atlas
constexpr int kNoiseUnit = 1;    // texture unit of the felt and wood noise
// The high preset's light: the linear ambient per unit of the full preset's ambient share, the
// exposure before tone mapping, the radiance of a shade's glowing mouth (linear, albedo 1 = 1)
// and the hall's own light against the lamps' (its walls and floor keep about the full preset's
// look: the tone curve's slope is about 1.4 at their light).
constexpr float kHighAmbientScale = 0.20f;
constexpr float kHighExposure = 3.0f;
constexpr float kMouthRadiance = 40.0f;
constexpr float kHallLevel = 0.7f / kHighExposure;

std::vector<std::unique_ptr<ShaderProgram>> compile(bool high) {
  std::vector<std::unique_ptr<ShaderProgram>> programs;
  for (int m = 0; m < shaders::kMaterials; ++m) {
    programs.push_back(
        std::make_unique<ShaderProgram>(shaders::kSceneVertex, shaders::withMaterial(m, high)));
  }
  return programs;
}

TextBitmap loadNumberAtlas() {
  return numberAtlas(TextRasterizer());
}

}  // namespace

SceneShading::SceneShading()
    : programs_(compile(false)),
      numbers_(loadNumberAtlas()),
      noise_(valueNoise(256, 32, 7), GpuTexture::Edges::Repeat) {}

const ShaderProgram& SceneShading::program(int material) const {
  return *active()[static_cast<std::size_t>(material)];
}

void SceneShading::beginFrame(const Camera& camera, int width, int height, glm::vec3 background,
                              const SpotLights& lights, const RenderOptions& options) const {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPolygonMode(GL_FRONT_AND_BACK, options.wireframe ? GL_LINE : GL_FILL);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  numbers_.bind(kNumbersUnit);
  noise_.bind(kNoiseUnit);
  const glm::mat4 view_projection = viewProjection(camera, aspect);
  high_ = options.physical;
  if (high_ && high_programs_.empty()) {
    high_programs_ = compile(true);
    if (marks_) applyChalkMarks(high_programs_);
  }
  for (const auto& p : active()) {
    p->use();
    p->set("uViewProj", view_projection);
    p->set("uEye", camera.eye);
    p->set("uLightPos[0]", lights.positions[0]);
    p->set("uLightPos[1]", lights.positions[1]);
    p->set("uCosInner", std::cos(glm::radians(lights.inner_deg)));
    p->set("uCosOuter", std::cos(glm::radians(lights.outer_deg)));
    p->set("uTextures", options.textures ? 1 : 0);
    p->set("uLighting", options.lighting ? 1 : 0);
    p->set("uNumbers", kNumbersUnit);
    p->set("uNoise", kNoiseUnit);
    p->set("uLampGain", kLampGain);
    p->set("uAlpha", 1.0f);
    if (!high_) continue;
    p->set("uShadow0", shaders::kShadowUnit0);
    p->set("uShadow1", shaders::kShadowUnit1);
    p->set("uEnvironment", shaders::kEnvironmentUnit);
    p->set("uShadowMaps", lights.shadow_matrices ? 1 : 0);
    if (lights.shadow_matrices) {
      p->set("uLightMatrix[0]", (*lights.shadow_matrices)[0]);
      p->set("uLightMatrix[1]", (*lights.shadow_matrices)[1]);
    }
    p->set("uShadowTexel", 1.0f / static_cast<float>(LampShadowMaps::kSize));
    p->set("uExposure", kHighExposure);
    p->set("uAmbientScale", kHighAmbientScale);
    p->set("uMouthRadiance", kMouthRadiance);
    p->set("uHallLevel", kHallLevel);
  }
  setAmbient(kAmbient);
}

void SceneShading::setAmbient(float ambient) const {
  for (const auto& p : active()) {
    p->use();
    p->set("uAmbient", ambient);
  }
}

void SceneShading::endFrame() const {
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

void SceneShading::draw(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, int material,
                        float specular) const {
  const ShaderProgram& p = program(material);
  p.use();
  p.set("uModel", model);
  p.set("uNormalMatrix", glm::mat3(glm::transpose(glm::inverse(model))));
  p.set("uColour", colour);
  p.set("uSpecular", specular);
  mesh.draw();
}

void SceneShading::drawFaded(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour,
                             int material, float alpha) const {
  const ShaderProgram& p = program(material);
  p.use();
  p.set("uAlpha", alpha);
  draw(mesh, model, colour, material, 0.0f);
  p.set("uAlpha", 1.0f);
}

void SceneShading::setChalkMarks(const ChalkMarks& marks) const {
  marks_ = marks;
  applyChalkMarks(programs_);
  if (!high_programs_.empty()) applyChalkMarks(high_programs_);
}

void SceneShading::applyChalkMarks(const Programs& programs) const {
  const ChalkMarks& marks = *marks_;
  const ShaderProgram& p = *programs[shaders::kMarkedFelt];
  p.use();
  const auto at = [](const Eigen::Vector2d& v) {
    return glm::vec2(static_cast<float>(v.x()), static_cast<float>(v.y()));
  };
  const table::SnookerSpots& s = marks.spots;
  p.set("uChalk", chalkColour());
  p.set("uBaulk", glm::vec4(static_cast<float>(s.baulk_x), static_cast<float>(s.d_radius),
                            marks.bed_half_width, ChalkMarks::kStrength));
  const Eigen::Vector2d* spots[] = {&s.yellow, &s.green, &s.brown, &s.blue, &s.pink, &s.black};
  for (int i = 0; i < 6; ++i) {
    const std::string name = "uSpots[" + std::to_string(i) + "]";
    p.set(name.c_str(), at(*spots[i]));
  }
  p.set("uMarkSize", glm::vec2(0.5f * ChalkMarks::kLineWidth, ChalkMarks::kSpotRadius));
}

void SceneShading::drawBall(const GpuMesh& sphere, const glm::mat4& model,
                            const BallLook& look) const {
  const ShaderProgram& p = program(shaders::kBall);
  p.use();
  p.set("uStriped", look.striped ? 1 : 0);
  p.set("uBallCell", look.number);
  draw(sphere, model, look.colour, shaders::kBall, 0.5f);
}

}  // namespace pool::render
