// GLSL 3.30 sources: the scene shader (world-space Blinn-Phong from two spotlights, procedural
// felt and wood, numbered balls) and the unlit overlay-line shader.
#pragma once

namespace pool::render::shaders {

/// Material codes of the scene shader's uMaterial.
enum Material : int { kPlain = 0, kFelt = 1, kWood = 2, kBall = 3, kEmissive = 4 };

/// Vertex stage: world position and normal, plus the object-space normal (ball markings turn
/// with the ball's orientation).
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

/// Fragment stage. Balls: solid colour, or white with a band |z| < 0.5 (stripes); a white circle
/// with the number (atlas cell uBallCell) on the body's +x and -x sides. Felt and wood modulate
/// brightness only, so their hue stays that of uColour. uLighting 0: albedo unlit.
inline constexpr const char* kSceneFragment = R"(#version 330 core
in vec3 vWorldPos;
in vec3 vNormal;
in vec3 vLocalNormal;
uniform vec3 uColour;
uniform int uMaterial;
uniform int uStriped;
uniform int uBallCell;
uniform int uTextures;
uniform int uLighting;
uniform float uSpecular;
uniform sampler2D uNumbers;
uniform vec3 uEye;
uniform vec3 uLightPos[2];
uniform float uCosInner;
uniform float uCosOuter;
out vec4 fragColour;
const vec3 kWhite = vec3(0.95, 0.95, 0.92);
const float kCircleCos = 0.9;  // number circle: about 26 degrees around the axis
float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
float noise(vec2 p) {
  vec2 i = floor(p), f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(i), hash(i + vec2(1, 0)), u.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), u.x), u.y);
}
vec3 ballAlbedo(vec3 n) {
  vec3 base = (uStriped == 1 && abs(n.z) > 0.5) ? kWhite : uColour;
  if (uTextures == 0 || uBallCell <= 0 || abs(n.x) < kCircleCos) return base;
  float side = n.x > 0.0 ? 1.0 : -1.0;
  vec2 uv = vec2(side * n.y, n.z) / sqrt(1.0 - kCircleCos * kCircleCos);
  vec2 cell = vec2(float(uBallCell % 4), float(uBallCell / 4));
  float ink = texture(uNumbers, (cell + vec2(0.5 + 0.5 * uv.x, 0.5 - 0.5 * uv.y)) / 4.0).r;
  return mix(kWhite, vec3(0.04), ink);
}
vec3 albedo() {
  if (uMaterial == 3) return ballAlbedo(normalize(vLocalNormal));
  if (uTextures == 0) return uColour;
  if (uMaterial == 1) {
    float fibre = noise(vWorldPos.xy * 900.0) * 0.08 + noise(vWorldPos.xy * 7.0) * 0.06;
    return uColour * (0.93 + fibre);
  }
  if (uMaterial == 2) {
    float along = abs(vNormal.x) > abs(vNormal.y) ? vWorldPos.y : vWorldPos.x;
    float across = vWorldPos.x + vWorldPos.y + vWorldPos.z;
    float grain = sin(across * 140.0 + noise(vec2(along * 9.0, across * 30.0)) * 6.0);
    return uColour * (0.88 + 0.12 * grain);
  }
  return uColour;
}
void main() {
  vec3 base = albedo();
  if (uLighting == 0 || uMaterial == 4) {
    fragColour = vec4(min(base, vec3(1.0)), 1.0);
    return;
  }
  vec3 n = normalize(vNormal);
  vec3 v = normalize(uEye - vWorldPos);
  if (dot(n, v) < 0.0) n = -n;
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

/// Overlay lines: position and colour per vertex, no lighting.
inline constexpr const char* kLineVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aColour;
uniform mat4 uViewProj;
out vec3 vColour;
void main() {
  vColour = aColour;
  gl_Position = uViewProj * vec4(aPos, 1.0);
}
)";

inline constexpr const char* kLineFragment = R"(#version 330 core
in vec3 vColour;
out vec4 fragColour;
void main() { fragColour = vec4(vColour, 1.0); }
)";

}  // namespace pool::render::shaders
