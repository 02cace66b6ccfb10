// The room's geometry (floor, walls, stool, ball, window, triangle) and its drawing.
#include "client/render/eight_ball_room.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "client/render/palette.h"
#include "client/render/shaders.h"

namespace pool::render {

namespace {

constexpr float kSeatHeight = 0.75f;  // m
constexpr float kSeatRadius = 0.32f;
constexpr float kSeatThickness = 0.05f;
constexpr float kWindowRadius = 0.42f;  // of the ball's radius
constexpr int kTextUnit = 2;
constexpr int kTextWidth = 256;
constexpr int kTextHeight = 192;
/// The text's box on the triangle (local frame: the triangle's in-circle has radius 0.5).
constexpr glm::vec4 kTextBox(-0.42f, -0.33f, 0.42f, 0.36f);

const glm::vec3 kBackground(0.03f, 0.02f, 0.05f);
const glm::vec3 kFloor(0.09f, 0.07f, 0.10f);
const glm::vec3 kWalls(0.50f, 0.38f, 0.56f);  // plum plaster
// The 8's number circle: its axis this far above the line to the default camera, so the whole
// circle shows on the ball's upper face (on the silhouette's edge it read as a flat cut).
constexpr float kCircleAboveView = 1.05f;  // rad, 60°
const glm::vec3 kWindow(0.01f, 0.01f, 0.04f);
const glm::vec3 kTriangle(0.10f, 0.22f, 0.85f);

/// A three-legged stool: the seat (rim and top) and its legs, feet on the floor at z = 0.
MeshData stoolMesh() {
  MeshData stool = openFrustum(kSeatRadius, kSeatRadius, kSeatThickness, 48);
  for (auto& p : stool.positions) p.z += kSeatHeight;
  MeshData top = unitDisc(48);
  for (auto& p : top.positions) p = p * kSeatRadius + glm::vec3(0, 0, kSeatHeight + kSeatThickness);
  append(stool, top);
  for (int leg = 0; leg < 3; ++leg) {
    const float angle = 2.0944f * static_cast<float>(leg) + 0.5f;
    const glm::vec3 at(0.24f * std::cos(angle), 0.24f * std::sin(angle), 0.0f);
    MeshData post = openFrustum(0.025f, 0.02f, kSeatHeight, 12);
    for (auto& p : post.positions) p += at;
    append(stool, post);
  }
  return stool;
}

/// The room's back wall and its two side walls, 3 m high, round the 8 m floor; normals inward.
MeshData wallsMesh() {
  MeshData walls;
  const float h = 3.0f;
  addQuad(walls, {-4.0f, 3.0f, 0.0f}, {4.0f, 3.0f, 0.0f}, {4.0f, 3.0f, h}, {-4.0f, 3.0f, h});
  addQuad(walls, {-4.0f, -4.0f, 0.0f}, {-4.0f, 3.0f, 0.0f}, {-4.0f, 3.0f, h}, {-4.0f, -4.0f, h});
  addQuad(walls, {4.0f, 3.0f, 0.0f}, {4.0f, -4.0f, 0.0f}, {4.0f, -4.0f, h}, {4.0f, 3.0f, h});
  return walls;
}

/// An equilateral triangle pointing down in the xy plane, its in-circle of radius 0.5 at 0.
MeshData triangleMesh() {
  MeshData tri;
  const glm::vec3 n(0, 0, 1);
  tri.positions = {{-0.866f, 0.5f, 0.0f}, {0.0f, -1.0f, 0.0f}, {0.866f, 0.5f, 0.0f}};
  tri.normals = {n, n, n};
  return tri;
}

/// A frame at `centre` whose local z points along `normal` and local y up as far as it can.
glm::mat4 facing(glm::vec3 centre, glm::vec3 normal, float scale) {
  const glm::vec3 z = glm::normalize(normal);
  const glm::vec3 x = glm::normalize(glm::cross(glm::vec3(0, 0, 1), z));
  const glm::vec3 y = glm::cross(z, x);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x * scale, 0.0f);
  m[1] = glm::vec4(y * scale, 0.0f);
  m[2] = glm::vec4(z * scale, 0.0f);
  m[3] = glm::vec4(centre, 1.0f);
  return m;
}

}  // namespace

EightBallRoom::EightBallRoom()
    : sphere_(unitSphere(48, 64)),
      disc_(unitDisc(64)),
      floor_(box({-4.0f, -4.0f, -0.02f}, {4.0f, 4.0f, 0.0f})),
      walls_(wallsMesh()),
      stool_(stoolMesh()),
      triangle_(triangleMesh()),
      decal_(shaders::kDecalVertex, shaders::kDecalFragment),
      answer_texture_(TextBitmap{1, 1, {0}}) {}

EightBallRoom::~EightBallRoom() = default;

Camera EightBallRoom::defaultCamera() {
  return {glm::vec3(0.0f, -3.3f, 2.1f), glm::vec3(0.0f, 0.0f, 1.1f), 40.0f};
}

glm::vec3 EightBallRoom::ballCentre() {
  return {0.0f, 0.0f, kSeatHeight + kSeatThickness + ballRadius() * 0.97f};
}

float EightBallRoom::ballRadius() {
  return 0.5f;
}

glm::vec3 EightBallRoom::windowCentre(const Camera& camera) {
  return ballCentre() + glm::normalize(camera.eye - ballCentre()) * ballRadius();
}

void EightBallRoom::drawWindow(const Camera& camera, float aspect, const std::string& answer) {
  const glm::vec3 toward = glm::normalize(camera.eye - ballCentre());
  const float r = ballRadius();
  // The window sits just proud of the surface; the triangle just proud of the window.
  const glm::mat4 window = facing(ballCentre() + toward * (r * 1.004f), toward, r * kWindowRadius);
  shading_.draw(disc_, window, kWindow, shaders::kEmissive, 0.0f);
  if (answer != shown_) {
    answer_texture_.upload(text_.draw(wrapWords(answer, 10), kTextWidth, kTextHeight, 72.0f));
    shown_ = answer;
  }
  const glm::mat4 face =
      facing(ballCentre() + toward * (r * 1.008f), toward, r * kWindowRadius * 0.95f);
  decal_.use();
  decal_.set("uViewProj", viewProjection(camera, aspect));
  decal_.set("uModel", face);
  decal_.set("uColour", kTriangle);
  decal_.set("uTextBox", kTextBox);
  decal_.set("uText", kTextUnit);
  answer_texture_.bind(kTextUnit);
  triangle_.draw();
}

void EightBallRoom::draw(const Camera& camera, int width, int height, const std::string& answer) {
  const SpotLights lights{
      {glm::vec3(-0.7f, -0.9f, 3.0f), glm::vec3(0.8f, -0.4f, 3.2f)}, 35.0f, 70.0f, std::nullopt};
  shading_.beginFrame(camera, width, height, kBackground, lights, options_);
  shading_.draw(floor_, glm::mat4(1.0f), kFloor, shaders::kPlain, 0.0f);
  shading_.draw(walls_, glm::mat4(1.0f), kWalls, shaders::kPlain, 0.0f);
  shading_.draw(stool_, glm::mat4(1.0f), woodColour(), shaders::kWood, 0.1f);
  // The 8 (body +x) turned toward the default camera's side (−y), then up by the view's own
  // elevation and kCircleAboveView; the window is drawn over the side facing us.
  const glm::vec3 view = defaultCamera().eye - ballCentre();
  const float up = std::atan2(view.z, -view.y) + kCircleAboveView;
  const glm::mat4 ball = glm::scale(
      glm::rotate(
          glm::rotate(glm::translate(glm::mat4(1.0f), ballCentre()), -up, glm::vec3(1, 0, 0)),
          -1.5707963f, glm::vec3(0, 0, 1)),
      glm::vec3(ballRadius()));
  shading_.drawBall(sphere_, ball, ballLook(8));
  drawWindow(camera, static_cast<float>(width) / static_cast<float>(height), answer);
  shading_.endFrame();
}

}  // namespace pool::render
