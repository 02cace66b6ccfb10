// GLSL 3.30 sources of the scene shader: world-space Blinn-Phong lighting from two spotlights.
#pragma once

namespace pool::render::shaders {

/// Vertex stage: world position and normal, plus the object-space normal (for ball stripes).
inline constexpr const char* kSceneVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;
out vec3 vWorldPos;
out vec3 vNormal;
out vec3 vLocalNormal;
void main() {
  vec4 world = uModel * vec4(aPos, 1.0);
  vWorldPos = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vLocalNormal = aNormal;
  gl_Position = uViewProj * world;
}
)";

/// Fragment stage: two downward spotlights with a soft cone, ambient, diffuse and specular terms.
/// Striped balls are white except for a band around their local y axis.
inline constexpr const char* kSceneFragment = R"(#version 330 core
in vec3 vWorldPos;
in vec3 vNormal;
in vec3 vLocalNormal;
uniform vec3 uColour;
uniform int uStriped;
uniform float uSpecular;
uniform vec3 uEye;
uniform vec3 uLightPos[2];
uniform float uCosInner;
uniform float uCosOuter;
out vec4 fragColour;
vec3 albedo() {
  if (uStriped == 1 && abs(vLocalNormal.y) > 0.5) return vec3(0.95, 0.95, 0.92);
  return uColour;
}
void main() {
  vec3 n = normalize(vNormal);
  vec3 v = normalize(uEye - vWorldPos);
  if (dot(n, v) < 0.0) n = -n;
  vec3 base = albedo();
  vec3 colour = 0.22 * base;
  for (int i = 0; i < 2; ++i) {
    vec3 l = normalize(uLightPos[i] - vWorldPos);
    float cone = smoothstep(uCosOuter, uCosInner, dot(-l, vec3(0.0, 0.0, -1.0)));
    float diffuse = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float spec = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), 64.0) : 0.0;
    colour += cone * (0.62 * diffuse * base + uSpecular * spec * vec3(1.0));
  }
  fragColour = vec4(min(colour, vec3(1.0)), 1.0);
}
)";

}  // namespace pool::render::shaders
