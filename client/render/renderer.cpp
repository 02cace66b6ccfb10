// Scene drawing: felt and wooden table parts (a snooker table's slate with its chalk marks),
// diamonds, pocket holes, the balls' shadows, numbered balls turned by their orientation, the cue,
// the lamps and the trough of pocketed balls, then the ghost ball's outline and the overlay lines
// on top.
#include "client/render/renderer.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <stdexcept>

#include "client/render/cue_shadow.h"
#include "client/render/hall_assets.h"
#include "client/render/hall_room.h"
#include "client/render/lamps.h"
#include "client/render/palette.h"
#include "client/render/shaders.h"
#include "client/render/table_dressing.h"

namespace pool::render {

namespace {

// Diamonds sit this far above the collision rails' top: over the dressing's rail top and rims.
constexpr float kDiamondLift = 3.0f * kRailCapLift;
constexpr glm::vec3 kBackground(0.10f, 0.10f, 0.12f);
constexpr float kTroughLight = 0.75f;  // share of the albedo lit in the trough
// The hall's light besides the lamps (walls and ceiling sending some back): the share of the
// albedo lit outside the pools.
constexpr float kHallLight = 0.38f;
constexpr glm::vec3 kDiamondColour(0.86f, 0.84f, 0.76f);  // mother of pearl
constexpr glm::vec3 kGhostColour(0.95f, 0.95f, 0.95f);
constexpr int kGhostSegments = 48;

glm::vec3 toGlm(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

std::vector<NamedMesh> roomOrThrow() {
  auto parts = loadRoom();
  if (!parts) throw std::runtime_error(parts.error());
  return std::move(*parts);
}

/// Collision parts the dressing draws instead: the rails (its rail tops, rounded edge and apron),
/// the pockets' cylinders (its liners) and the channel under the slate (inside the apron, seen
/// only through a pocket, where the liner's cup is).
bool dressedOver(const std::string& part) {
  return part.rfind("rail_", 0) == 0 || part.rfind("pocket_", 0) == 0 || part == "trough";
}

std::vector<CueMeshPart> cueMeshOrThrow() {
  auto parts = loadCueAsset();
  if (!parts) throw std::runtime_error(parts.error());
  return std::move(*parts);
}

/// The cue frame's model matrix: its +x (tip → butt) along −forward, its tip at `tip`.
glm::mat4 cueModelMatrix(const CuePlacement& cue) {
  const glm::vec3 x = -cue.forward;
  const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), x));
  const glm::vec3 up = glm::cross(x, side);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x, 0.0f);
  m[1] = glm::vec4(side, 0.0f);
  m[2] = glm::vec4(up, 0.0f);
  m[3] = glm::vec4(cue.tip, 1.0f);
  return m;
}

}  // namespace

CueObstacles cueObstaclesOf(const Scene& scene, glm::vec3 cue_ball) {
  const RailExtent rails = railExtent(scene.geometry, static_cast<float>(scene.cushion_width));
  CueObstacles obstacles{rails.half_length,
                         rails.half_width,
                         rails.cushion_width + rails.rail_width,
                         rails.top,
                         static_cast<float>(scene.ball_radius),
                         {}};
  for (const SceneBall& b : scene.balls) {
    const glm::vec3 at = toGlm(b.pos);
    if (b.pocketed || glm::length(at - cue_ball) < 1e-4f) continue;
    obstacles.balls.push_back(at);
  }
  return obstacles;
}

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      trough_(scene.geometry, scene.ball_radius, troughSlotsFor(scene.ball_set)),
      sphere_(unitSphere(16, 24)),
      shade_(lampShade()),
      bulb_(unitSphere(8, 12)),
      diamond_(diamondInlay()),
      rails_(railExtent(scene.geometry, static_cast<float>(scene.cushion_width))),
      cue_model_(cueMeshOrThrow()) {
  for (const auto& part : scene_.geometry.parts) {
    if (part.triangles.empty() || dressedOver(part.name)) continue;
    PartLook look = partLook(part.name);
    // A snooker table's slate carries the chalk of its baulk line, D and spots.
    if (scene_.snooker_marks && look.material == shaders::kFelt && part.name == "slate") {
      look.material = shaders::kMarkedFelt;
    }
    parts_.push_back({std::make_unique<GpuMesh>(meshFromPart(part)), look.colour, look.material});
  }
  if (scene_.snooker_marks) {
    shading_.setChalkMarks(
        {*scene_.snooker_marks, static_cast<float>(scene_.geometry.width) * 0.5f});
  }
  parts_.push_back({std::make_unique<GpuMesh>(trough_.mesh()), woodColour(), shaders::kWood});
  for (const NamedMesh& part :
       loadDressing(scene_.geometry, static_cast<float>(scene_.cushion_width))) {
    const PartLook look = hallPartLook(part.name);
    parts_.push_back({std::make_unique<GpuMesh>(part.mesh), look.colour, look.material});
  }
  for (const NamedMesh& part : roomOrThrow()) {
    const PartLook look = hallPartLook(part.name);
    room_.push_back(
        {std::make_unique<GpuMesh>(part.mesh), look.colour, look.material, isHallShell(part.name)});
  }
  diamonds_ = diamondPositions(rails_);
  trough_.update(scene_.balls);
  updateShadows();
}

void Renderer::setBalls(std::vector<SceneBall> balls) {
  scene_.balls = std::move(balls);
  trough_.update(scene_.balls);
  placeCue();
}

void Renderer::setOptions(const RenderOptions& options) {
  const bool shadows_changed = options.shadow_maps != options_.shadow_maps;
  options_ = options;
  if (shadows_changed) updateShadows();
}

std::vector<glm::vec3> Renderer::keepClear() const {
  if (!keep_clear_.empty()) return keep_clear_;
  std::vector<glm::vec3> balls;
  for (const SceneBall& b : scene_.balls) {
    if (!b.pocketed) balls.push_back(toGlm(b.pos));
  }
  return balls;
}

void Renderer::setOverlay(std::vector<OverlayLine> lines) {
  overlay_.set(lines);
}

void Renderer::setCue(std::optional<CueAim> aim) {
  cue_aim_ = aim;
  placeCue();
}

void Renderer::placeCue() {
  cue_.reset();
  if (cue_aim_)
    cue_ = pool::render::placeCue(*cue_aim_, cueObstaclesOf(scene_, cue_aim_->cue_ball));
  updateShadows();
}

void Renderer::updateShadows() {
  std::vector<glm::vec3> centres;
  for (const SceneBall& b : scene_.balls) {
    if (!b.pocketed) centres.push_back(toGlm(b.pos));
  }
  const auto lamps = lampPositions(scene_.geometry);
  const auto radius = static_cast<float>(scene_.ball_radius);
  // With shadow maps the lamps' shadows are the maps': the contact shadows and the cushions'
  // shade stay.
  const std::span<const glm::vec3> casting =
      options_.shadow_maps ? std::span<const glm::vec3>() : std::span<const glm::vec3>(lamps);
  auto blobs = ballShadows(casting, centres, radius, SceneShading::kAmbient);
  for (const auto& blob : ballShadowsOnCushions(lamps, centres, radius, rails_.half_length,
                                                rails_.half_width, rails_.top)) {
    blobs.push_back(blob);
  }
  if (cue_ && !options_.shadow_maps) {
    for (const auto& piece :
         cueShadow(lamps, *cue_, rails_.half_length, rails_.half_width, SceneShading::kAmbient)) {
      blobs.push_back(piece);
    }
    for (const auto& piece : cueShadowOnRails(lamps, *cue_, rails_, SceneShading::kAmbient)) {
      blobs.push_back(piece);
    }
  }
  const float outer = rails_.cushion_width + rails_.rail_width;
  shadows_.setTableExtent({rails_.half_length, rails_.half_width},
                          {rails_.half_length + outer, rails_.half_width + outer});
  shadows_.set(blobs);
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

void Renderer::drawDiamonds() const {
  for (const glm::vec3& at : diamonds_) {
    // Long diagonal along the rail: x on the long rails, y on the end rails.
    const bool end_rail = std::abs(at.x) > rails_.half_length;
    glm::mat4 model = glm::translate(glm::mat4(1.0f), at + glm::vec3(0.0f, 0.0f, kDiamondLift));
    if (end_rail) model = glm::rotate(model, glm::radians(90.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    shading_.draw(diamond_, model, kDiamondColour, shaders::kEmissive, 0.0f);
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
    shading_.drawBall(sphere_, model, ballLook(ball.id, scene_.ball_set));
    if (ball.pocketed) shading_.setAmbient(kHallLight);
  }
}

void Renderer::drawCue(const Camera& camera) const {
  if (!cue_) return;
  const glm::mat4 model = cueModelMatrix(*cue_);
  // A cue passing by the eye would fill the view: it turns translucent instead.
  const float alpha = cueOpacity(*cue_, camera.eye);
  if (alpha < 1.0f) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  }
  for (const CueModel::Part& part : cue_model_.parts()) {
    if (alpha < 1.0f) {
      shading_.drawFaded(*part.mesh, model, part.look.colour, part.look.material, alpha);
    } else {
      shading_.draw(*part.mesh, model, part.look.colour, part.look.material, part.look.specular);
    }
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void Renderer::drawLamps(const Camera& camera, int width, int height) const {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const std::vector<glm::vec3> keep_clear = keepClear();
  for (const glm::vec3& light : lampPositions(scene_.geometry)) {
    const float alpha = lampOpacity(camera, width, height, light, keep_clear);
    if (alpha <= 0.0f) continue;  // out of the way: the light still falls on the table
    glDepthMask(alpha < 1.0f ? GL_FALSE : GL_TRUE);
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), light);
    shading_.drawFaded(shade_, at, shadeColour(), shaders::kShade, alpha);
    const glm::mat4 bulb = glm::scale(at, glm::vec3(kBulbRadius));
    shading_.drawFaded(bulb_, bulb, bulbColour(), shaders::kEmissive, alpha);
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void Renderer::drawGhost(const Camera& camera, const glm::mat4& view_projection) const {
  if (!ghost_) {
    ghost_lines_.set({});
    return;
  }
  // The ball's silhouette: a circle of radius R about its centre, across the line of sight; two
  // rings a pixel or so apart for a visible outline.
  const glm::vec3 sight = glm::normalize(*ghost_ - camera.eye);
  const glm::vec3 right = glm::normalize(glm::cross(sight, camera.up));
  const glm::vec3 up = glm::cross(right, sight);
  std::vector<OverlayLine> lines;
  const auto r = static_cast<float>(scene_.ball_radius);
  for (const float scale : {1.0f, 0.96f}) {
    for (int i = 0; i < kGhostSegments; ++i) {
      const float a0 = 6.2831853f * static_cast<float>(i) / kGhostSegments;
      const float a1 = 6.2831853f * static_cast<float>(i + 1) / kGhostSegments;
      const auto at = [&](float a) {
        return *ghost_ + scale * r * (std::cos(a) * right + std::sin(a) * up);
      };
      lines.push_back({at(a0), at(a1), kGhostColour});
    }
  }
  ghost_lines_.set(lines);
  ghost_lines_.draw(view_projection);
}

void Renderer::draw(const Camera& camera, int width, int height) const {
  const bool scaled = options_.scale < 1.0f && options_.scale > 0.0f;
  if (scaled) {
    const auto part = [&](int n) {
      return std::max(1, static_cast<int>(std::lround(static_cast<float>(n) * options_.scale)));
    };
    scaled_.begin(part(width), part(height));
    drawScene(camera, part(width), part(height));
    scaled_.end(width, height);
  } else if (options_.samples > 1) {
    scaled_.begin(width, height, options_.samples);
    drawScene(camera, width, height);
    scaled_.end(width, height);
  } else {
    drawScene(camera, width, height);
  }
}

void Renderer::renderShadowMaps() const {
  if (!shadow_maps_) shadow_maps_ = std::make_unique<LampShadowMaps>();
  const auto lamps = lampPositions(scene_.geometry);
  const auto r = static_cast<float>(scene_.ball_radius);
  for (int i = 0; i < 2; ++i) {
    shadow_maps_->begin(i, lamps[static_cast<std::size_t>(i)]);
    for (const Part& part : parts_) shadow_maps_->caster(*part.mesh, glm::mat4(1.0f));
    for (const SceneBall& ball : scene_.balls) {
      if (ball.pocketed) continue;
      shadow_maps_->caster(
          sphere_, glm::scale(glm::translate(glm::mat4(1.0f), toGlm(ball.pos)), glm::vec3(r)));
    }
    if (cue_) {
      for (const CueModel::Part& part : cue_model_.parts()) {
        shadow_maps_->caster(*part.mesh, cueModelMatrix(*cue_));
      }
    }
    shadow_maps_->end();
    shadow_maps_->bind(i, i == 0 ? shaders::kShadowUnit0 : shaders::kShadowUnit1);
  }
}

void Renderer::captureEnvironment() const {
  environment_ = std::make_unique<EnvironmentMap>();
  const auto lamps = lampPositions(scene_.geometry);
  // Over the table's centre, about where the balls' tops see the hall from.
  environment_->capture(glm::vec3(0.0f, 0.0f, 0.25f), [&](const Camera& camera) {
    RenderOptions plain;
    plain.textures = options_.textures;
    shading_.beginFrame(camera, EnvironmentMap::kSize, EnvironmentMap::kSize, kBackground,
                        {lamps, kSpotInnerDeg, kSpotOuterDeg, std::nullopt}, plain);
    shading_.setAmbient(kHallLight);
    drawTable();
    drawRoom();
    for (const glm::vec3& light : lamps) {
      const glm::mat4 at = glm::translate(glm::mat4(1.0f), light);
      shading_.draw(shade_, at, shadeColour(), shaders::kShade, 0.0f);
      shading_.draw(bulb_, glm::scale(at, glm::vec3(kBulbRadius)), bulbColour(), shaders::kEmissive,
                    0.0f);
    }
    shading_.endFrame();
  });
}

void Renderer::drawTable() const {
  for (const Part& part : parts_) {
    shading_.draw(*part.mesh, glm::mat4(1.0f), part.colour, part.material, 0.05f);
  }
  drawDiamonds();
}

void Renderer::drawRoom() const {
  if (!options_.room) return;
  for (const Part& part : room_) {
    // The shell (floor, walls, ceiling) is seen from inside only: a camera zoomed out beyond
    // a wall or over the ceiling looks through it, as into a doll's house.
    if (part.shell) glEnable(GL_CULL_FACE);
    shading_.draw(*part.mesh, glm::mat4(1.0f), part.colour, part.material, 0.0f);
    glDisable(GL_CULL_FACE);
  }
}

void Renderer::drawScene(const Camera& camera, int width, int height) const {
  const auto lamps = lampPositions(scene_.geometry);
  const glm::mat4 view_projection =
      viewProjection(camera, static_cast<float>(width) / static_cast<float>(height));
  SpotLights lights{lamps, kSpotInnerDeg, kSpotOuterDeg, std::nullopt};
  if (options_.physical) {
    if (!environment_) captureEnvironment();
    environment_->bind(shaders::kEnvironmentUnit);
    lights.inner_deg = kHighSpotInnerDeg;
    lights.outer_deg = kHighSpotOuterDeg;
  }
  if (options_.shadow_maps && options_.lighting && !options_.wireframe) {
    renderShadowMaps();
    lights.shadow_matrices = shadow_maps_->matrices();
  }
  shading_.beginFrame(camera, width, height, kBackground, lights, options_);
  shading_.setAmbient(kHallLight);
  drawTable();
  if (options_.lighting && !options_.wireframe) shadows_.draw(view_projection);
  drawBalls();
  drawCue(camera);
  // The hall last among the opaque things: the table and balls in front of it hide most of it
  // from the fragment shader.
  drawRoom();
  drawLamps(camera, width, height);
  shading_.endFrame();
  drawGhost(camera, view_projection);
  overlay_.draw(view_projection);
}

}  // namespace pool::render
