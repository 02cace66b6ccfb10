// Shadow quads: corners in the slate plane, the ellipse's own coordinates and darkness per vertex.
#include "client/render/shadow_layer.h"

#include <glad/gl.h>

#include "client/render/mesh.h"

namespace pool::render {

namespace {

constexpr float kLift = 0.0004f;  // m above the slate

constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aShape;  // ellipse coordinates (−1..1) and darkness
uniform mat4 uViewProj;
out vec3 vShape;
out vec3 vPos;
void main() {
  vShape = aShape;
  vPos = aPos;
  gl_Position = uViewProj * vec4(aPos, 1.0);
}
)";

// Full darkness in the umbra, fading over the outer part (the lamp's bulb has a size).
// A shadow on the rails' top (raised) shows only between the playing surface and the table's
// edge.
constexpr const char* kFragment = R"(#version 330 core
in vec3 vShape;
in vec3 vPos;
uniform vec4 uExtent;  // the playing surface's half-extents, then the table edge's
out vec4 fragColour;
void main() {
  float r = length(vShape.xy);
  if (r >= 1.0) discard;
  if (vPos.z > 0.01) {
    vec2 a = abs(vPos.xy);
    if (all(lessThanEqual(a, uExtent.xy)) || any(greaterThan(a, uExtent.zw))) discard;
  }
  fragColour = vec4(0.0, 0.0, 0.0, vShape.z * (1.0 - smoothstep(0.55, 1.0, r)));
}
)";

}  // namespace

ShadowLayer::ShadowLayer() : program_(kVertex, kFragment) {
  createVec3PairArray(vao_, vbo_);
  glBindVertexArray(0);
}

ShadowLayer::~ShadowLayer() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void ShadowLayer::set(const std::vector<ShadowBlob>& blobs) {
  std::vector<float> data;
  data.reserve(blobs.size() * 36);
  for (const ShadowBlob& b : blobs) {
    const glm::vec2 u = b.along * b.half_along;
    const glm::vec2 v = glm::vec2(-b.along.y, b.along.x) * b.half_across;
    const auto corner = [&](float s, float t) {
      const glm::vec2 p = b.centre + s * u + t * v;
      data.insert(data.end(), {p.x, p.y, b.z + kLift, b.soft_ends ? s : 0.0f, t, b.darkness});
    };
    corner(-1, -1), corner(1, -1), corner(1, 1);
    corner(-1, -1), corner(1, 1), corner(-1, 1);
  }
  vertices_ = static_cast<int>(data.size() / 6);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_DYNAMIC_DRAW);
}

void ShadowLayer::draw(const glm::mat4& view_projection) const {
  if (vertices_ == 0) return;
  program_.use();
  program_.set("uViewProj", view_projection);
  program_.set("uExtent", glm::vec4(playing_, edge_));
  glEnable(GL_BLEND);
  glBlendFunc(GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -2.0f);
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, vertices_);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace pool::render
