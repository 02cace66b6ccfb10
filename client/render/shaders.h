// GLSL 3.30 sources: the scene shader (world-space Blinn-Phong from two spotlights, procedural
// felt and wood, a snooker table's chalk marks, numbered balls, the cue's varnished wood, the lamp
// shades; and the high preset's variant: linear light through each lamp's shadow map, tone
// mapped, the balls' clear coat reflecting the hall's environment map and the lamps' mouths,
// cloth weave and nap, varnish and leather), the shadow maps' depth shader and the unlit
// overlay-line shader.
#pragma once

#include <string>

namespace pool::render::shaders {

/// Material codes of the scene shader's uMaterial.
enum Material : int {
  kPlain = 0,
  kFelt = 1,
  kWood = 2,
  kBall = 3,
  kEmissive = 4,
  kCue = 5,    ///< varnished wood with grain along the model's x axis, glossy
  kShade = 6,  ///< lamp shade: enamel outside (lit from the room), glowing inside
  // The hall's materials: lit by the room's light alone (the table and the walls sending the
  // lamps' light back), no spotlight work per fragment.
  kFloor = 7,       ///< oak planks along x, staggered joints
  kWall = 8,        ///< striped wallpaper
  kRoomWood = 9,    ///< panelling and furniture: the table's grain
  kRoomPlain = 10,  ///< flat colour
  kLiner = 11,      ///< a pocket's leather, darker the deeper inside
  /// A snooker table's slate: the felt with the chalk of its baulk line, D and spots
  /// (SceneShading::setChalkMarks), each mark antialiased by the share of a pixel it covers.
  kMarkedFelt = 12,
  kMaterials = 13
};

/// Texture units of the high variant: each lamp's shadow map and the hall's environment map.
inline constexpr int kShadowUnit0 = 2;
inline constexpr int kShadowUnit1 = 3;
inline constexpr int kEnvironmentUnit = 4;

/// Vertex stage: world position and normal, plus the object-space normal and position (ball
/// markings turn with the ball's orientation; the cue's grain runs along its own axis).
inline constexpr const char* kSceneVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;
out vec3 vWorldPos;
out vec3 vNormal;
out vec3 vLocalNormal;
out vec3 vLocalPos;
void main() {
  vec4 world = uModel * vec4(aPos, 1.0);
  vWorldPos = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vLocalNormal = aNormal;
  vLocalPos = aPos;
  gl_Position = uViewProj * world;
}
)";

/// Fragment stage, compiled once per material (withMaterial): llvmpipe runs every branch of a
/// shader, so each material's program holds only its own work.
/// Balls: solid colour, or white with a band |z| < 0.5 (stripes); a white circle with the number
/// (atlas cell uBallCell) on the body's +x and -x sides. Felt and wood modulate brightness with a
/// tiling noise texture, so their hue stays that of uColour. The marked felt mixes uChalk into
/// the felt by the share of the pixel's footprint a mark covers (a mark thinner than a pixel
/// shows fainter, never broken). uLighting 0: albedo unlit. Lamp light
/// falls off as (lamp height / distance)², so each lamp makes its own pool on the felt. uAlpha:
/// the fragment's opacity (fading lamps). HIGH (the high preset): albedos taken to linear light,
/// each lamp's light times its shadow map's visibility (a 3 × 3 percentage-closer filter of
/// bilinear comparisons, 1.5 texels apart: soft edges), tone mapped (ACES, Narkowicz 2015) and
/// encoded for display; the balls' clear coat (Schlick's Fresnel, F0 0.04) reflects the environment
/// map and the glowing mouth of each lamp's shade (a disc of kMouth m round the light); the felt
/// gets a woven texture and a nap's sheen at grazing angles, the wood a varnish, the liners a
/// leather grain and sheen.
inline constexpr const char* kSceneFragment = R"(
in vec3 vWorldPos;
in vec3 vNormal;
in vec3 vLocalNormal;
in vec3 vLocalPos;
uniform vec3 uColour;
uniform int uStriped;
uniform int uBallCell;
uniform int uTextures;
uniform int uLighting;
uniform float uSpecular;
uniform float uAmbient;
uniform float uAlpha;
uniform float uLampGain;
uniform sampler2D uNumbers;
uniform sampler2D uNoise;
uniform vec3 uEye;
uniform vec3 uLightPos[2];
uniform float uCosInner;
uniform float uCosOuter;
out vec4 fragColour;
#ifdef HIGH
uniform sampler2DShadow uShadow0;
uniform sampler2DShadow uShadow1;
uniform mat4 uLightMatrix[2];
uniform int uShadowMaps;  // 0: the lamps' light unshadowed
uniform float uShadowTexel;
uniform samplerCube uEnvironment;
uniform float uExposure;
uniform float uAmbientScale;  // linear ambient per unit of uAmbient
uniform float uMouthRadiance;
uniform float uHallLevel;  // the room's own light against the lamps' (linear)
const float kMouth = 0.20;  // m: the shade's glowing rim round the light
vec3 toLinear(vec3 c) { return pow(max(c, vec3(0.0)), vec3(2.2)); }
vec3 toDisplay(vec3 c) {
  vec3 x = c * uExposure;
  vec3 t = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  return pow(t, vec3(1.0 / 2.2));
}
float schlick(float cos_view) {
  float m = 1.0 - clamp(cos_view, 0.0, 1.0);
  return 0.04 + 0.96 * m * m * m * m * m;
}
float filtered(sampler2DShadow map, vec3 c) {
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) {
      sum += texture(map, vec3(c.xy + 1.5 * vec2(float(x), float(y)) * uShadowTexel, c.z));
    }
  }
  return sum / 9.0;
}
// The share of lamp i's light that reaches this fragment: 1 outside its map.
float visibility(int i, vec3 n) {
  if (uShadowMaps == 0) return 1.0;
  vec4 p = uLightMatrix[i] * vec4(vWorldPos + n * 0.003, 1.0);
  if (p.w <= 0.0) return 1.0;
  vec3 c = p.xyz / p.w * 0.5 + 0.5;
  if (any(lessThan(c, vec3(0.0))) || any(greaterThan(c, vec3(1.0)))) return 1.0;
  return i == 0 ? filtered(uShadow0, c) : filtered(uShadow1, c);
}
#endif
const vec3 kWhite = vec3(0.95, 0.95, 0.92);
const float kCircleCos = 0.9;  // number circle: about 26 degrees around the axis
#if MATERIAL == 1 || MATERIAL == 12
vec3 feltAlbedo() {
  if (uTextures == 0) return uColour;
  float fibre = texture(uNoise, vWorldPos.xy * 6.0).r * 0.08;
  float broad = texture(uNoise, vWorldPos.xy * 0.35).r * 0.06;
#ifdef HIGH
  // The weave: warp and weft 1.2 mm apart, faded out where a pixel spans a thread or more.
  vec2 threads = vWorldPos.xy / 0.0012;
  float fade = clamp(1.5 - 2.0 * max(fwidth(threads.x), fwidth(threads.y)), 0.0, 1.0);
  float weave = sin(6.2831853 * threads.x) * sin(6.2831853 * threads.y);
  return uColour * (0.93 + fibre + broad) * (1.0 + 0.07 * fade * weave);
#else
  return uColour * (0.93 + fibre + broad);
#endif
}
#endif
#if MATERIAL == 12
uniform vec3 uChalk;
uniform vec4 uBaulk;     // the baulk line's x, the D's radius, the bed's half width, chalk's share
uniform vec2 uSpots[6];  // yellow, green, brown (the D's centre), blue, pink, black
uniform vec2 uMarkSize;  // half a line's width, a spot's radius
// The share of one pixel's footprint (across d) inside |d| < w: d across a line, m.
float cover(float d, float w) {
  float f = max(fwidth(d), 1e-5);
  return clamp((min(d + 0.5 * f, w) - max(d - 0.5 * f, -w)) / f, 0.0, 1.0);
}
float chalk() {
  vec2 p = vWorldPos.xy;
  float line = cover(p.x - uBaulk.x, uMarkSize.x) * step(abs(p.y), uBaulk.z);
  float arc = cover(length(p - uSpots[2]) - uBaulk.y, uMarkSize.x) * step(p.x, uBaulk.x);
  float spot = 0.0;
  for (int i = 0; i < 6; ++i) spot = max(spot, cover(length(p - uSpots[i]), uMarkSize.y));
  // On the slate's top only, not down the faces of its pocket cuts.
  return step(abs(vWorldPos.z), 1e-3) * max(line, max(arc, spot));
}
#endif
vec3 albedo() {
#if MATERIAL == 3
  vec3 n = normalize(vLocalNormal);
  vec3 base = (uStriped == 1 && abs(n.z) > 0.5) ? kWhite : uColour;
  if (uTextures == 0 || uBallCell <= 0 || abs(n.x) < kCircleCos) return base;
  float side = n.x > 0.0 ? 1.0 : -1.0;
  vec2 uv = vec2(side * n.y, n.z) / sqrt(1.0 - kCircleCos * kCircleCos);
  vec2 cell = vec2(float(uBallCell % 4), float(uBallCell / 4));
  float ink = texture(uNumbers, (cell + vec2(0.5 + 0.5 * uv.x, 0.5 - 0.5 * uv.y)) / 4.0).r;
  return mix(kWhite, vec3(0.04), ink);
#elif MATERIAL == 1
  return feltAlbedo();
#elif MATERIAL == 12
  return mix(feltAlbedo(), uChalk, uBaulk.w * chalk());
#elif MATERIAL == 2 || MATERIAL == 9
  if (uTextures == 0) return uColour;
  float along = abs(vNormal.x) > abs(vNormal.y) ? vWorldPos.y : vWorldPos.x;
  float across = vWorldPos.x + vWorldPos.y + vWorldPos.z;
  float grain = sin(across * 140.0 + texture(uNoise, vec2(along * 0.3, across * 1.2)).r * 6.0);
  return uColour * (0.88 + 0.12 * grain);
#elif MATERIAL == 5
  if (uTextures == 0) return uColour;
  float around = atan(vLocalPos.z, vLocalPos.y);
  float streak = texture(uNoise, vec2(vLocalPos.x * 0.7, around * 0.9)).r;
  return uColour * (0.84 + 0.3 * streak);
#elif MATERIAL == 7
  if (uTextures == 0) return uColour;
  const float kPlank = 0.14, kRun = 1.8;
  float plank = floor(vWorldPos.y / kPlank);
  float shift = fract(plank * 0.37) * kRun;  // joints staggered from plank to plank
  float run = (vWorldPos.x + shift) / kRun;
  float tone = fract(sin(plank * 12.9898 + floor(run) * 78.233) * 43758.5453);
  float grain = texture(uNoise, vec2(vWorldPos.x * 0.12, vWorldPos.y * 2.5 + plank * 0.3)).r;
  float fy = fract(vWorldPos.y / kPlank), fx = fract(run);
  float seam = smoothstep(0.0, 0.04, fy) * smoothstep(1.0, 0.96, fy) *
               smoothstep(0.0, 0.003, fx) * smoothstep(1.0, 0.997, fx);
  return uColour * (0.75 + 0.35 * tone) * (0.82 + 0.3 * grain) * (0.45 + 0.55 * seam);
#elif MATERIAL == 8
  if (uTextures == 0) return uColour;
  float s = fract((vWorldPos.x + vWorldPos.y) / 0.16);
  float line = smoothstep(0.025, 0.0, abs(s - 0.5));
  return mix(uColour * (s < 0.5 ? 1.0 : 0.8), vec3(0.55, 0.44, 0.2), 0.6 * line);
#elif MATERIAL == 11
  float deep = mix(0.12, 1.0, smoothstep(-0.09, 0.0, vWorldPos.z));
#ifdef HIGH
  if (uTextures != 0) deep *= 0.85 + 0.3 * texture(uNoise, vWorldPos.xy * 9.0 + vWorldPos.z).r;
#endif
  return uColour * deep;
#else
  return uColour;
#endif
}
// The hall's light: the room's ambient, more on faces turned up, and the lamps' light sent back
// by the table, falling off away from it.
vec3 roomLit(vec3 base, vec3 n) {
  float near = clamp(1.0 - length(vWorldPos.xy) / 6.5, 0.0, 1.0);
  return base * (uAmbient * (0.9 + 0.4 * max(n.z, 0.0)) + 0.5 * near);
}
const vec3 kGlow = vec3(1.0, 0.9, 0.7);  // a shade's inside, lit by its bulb
#ifdef HIGH
// Lamp i's light on a surface of normal n here: cone × (height / distance)² × cos(incidence).
float lampLight(int i, vec3 n, out vec3 l) {
  vec3 to_light = uLightPos[i] - vWorldPos;
  float dist2 = dot(to_light, to_light);
  l = to_light * inversesqrt(dist2);
  float cone = smoothstep(uCosOuter, uCosInner, l.z);
  float falloff = uLightPos[i].z * uLightPos[i].z / dist2;
  return cone * falloff * uLampGain * max(dot(n, l), 0.0);
}
// The lamps' mouths mirrored in a clear coat: a bright disc where the reflected view meets one.
vec3 mouths(vec3 n, vec3 v) {
  vec3 r = reflect(-v, n);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < 2; ++i) {
    vec3 to_light = uLightPos[i] - vWorldPos;
    float dist = length(to_light);
    float c = cos(atan(kMouth / dist));
    sum += kGlow * smoothstep(c, mix(c, 1.0, 0.5), dot(r, to_light / dist)) *
           visibility(i, n);
  }
  return uMouthRadiance * sum;
}
// Every lit material but the room's and the shades': linear light in, linear light out.
vec3 litHigh(vec3 base, vec3 n, vec3 v) {
#if MATERIAL == 1 || MATERIAL == 12
  // Wool's dye is duller than its colour in linear light makes it.
  base = mix(vec3(dot(base, vec3(0.2126, 0.7152, 0.0722))), base, 0.8);
#endif
  vec3 colour = uAmbient * uAmbientScale * base;
  float nv = max(dot(n, v), 0.0);
  for (int i = 0; i < 2; ++i) {
    vec3 l;
    float light = lampLight(i, n, l);
    if (light > 0.0) light *= visibility(i, n);
#if MATERIAL == 1 || MATERIAL == 12
    // The nap: the cloth's fibres catch light at grazing view (a sheen, Ashikhmin's velvet).
    float sheen = 0.35 * pow(1.0 - nv, 3.0);
    colour += light * base * (1.0 + sheen);
#else
    colour += light * base;
#endif
#if MATERIAL == 2 || MATERIAL == 5
    // The varnish's highlight (the balls mirror the lamps' mouths instead).
    float s = max(dot(n, normalize(l + v)), 0.0);
    s *= s; s *= s; s *= s; s *= s; s *= s; s *= s; s *= s;  // ^128
    colour += light * 2.0 * uSpecular * s * vec3(1.0);
#endif
  }
#if MATERIAL == 3 || MATERIAL == 2 || MATERIAL == 5
  // A clear coat (the balls' resin, the varnish): Fresnel-weighted reflection of the hall.
  float f = schlick(nv);
  vec3 hall = toLinear(textureLod(uEnvironment, reflect(-v, n), MATERIAL == 3 ? 0.0 : 2.0).rgb);
#if MATERIAL == 3
  colour = colour * (1.0 - f) + f * (hall + mouths(n, v));
#else
  // Varnish: a thinner, rougher coat (the mirrored mouths a soft streak, not a line).
  colour = colour * (1.0 - 0.5 * f) + f * (0.5 * hall + 0.1 * mouths(n, v));
#endif
#endif
  return colour;
}
// The room's materials in linear light: the hall's light as before, and the lamps' own where
// their cones reach (the floor beside the table), shadowed by the table.
vec3 roomHigh(vec3 base, vec3 n) {
  float near = clamp(1.0 - length(vWorldPos.xy) / 6.5, 0.0, 1.0);
  float hall = uAmbient * (0.9 + 0.4 * max(n.z, 0.0)) + 0.5 * near;
  vec3 colour = base * pow(hall, 2.2) * uHallLevel;
  for (int i = 0; i < 2; ++i) {
    vec3 l;
    float light = lampLight(i, n, l);
    if (light > 0.0) colour += base * light * visibility(i, n);
  }
#if MATERIAL == 11
  // Leather: a soft sheen.
  vec3 v = normalize(uEye - vWorldPos);
  colour += 0.08 * schlick(max(dot(n, v), 0.0)) * pow(hall, 2.2) * uHallLevel;
#endif
  return colour;
}
#endif
void main() {
  vec3 base = albedo();
#if MATERIAL == 4
  fragColour = vec4(min(base, vec3(1.0)), uAlpha);
#else
  if (uLighting == 0) {
    fragColour = vec4(min(base, vec3(1.0)), uAlpha);
    return;
  }
  vec3 n = normalize(vNormal);
  vec3 v = normalize(uEye - vWorldPos);
  bool inside = dot(n, v) < 0.0;
  if (inside) n = -n;
#if MATERIAL >= 7 && MATERIAL <= 11
#ifdef HIGH
  fragColour = vec4(toDisplay(roomHigh(toLinear(base), n)), uAlpha);
#else
  fragColour = vec4(min(roomLit(base, n), vec3(1.0)), uAlpha);
#endif
  return;
#endif
#if MATERIAL == 6
  // Inside: the bulb's glow, brightest toward the rim it spills from. Outside: enamel under the
  // light the room sends back up from the table, with a sheen.
  if (inside) {
    fragColour = vec4(kGlow * (0.75 + 0.25 * smoothstep(0.0, 0.15, -vLocalPos.z + 0.14)), uAlpha);
    return;
  }
  float fill = 0.35 + 0.45 * max(-n.z, 0.0) + 0.25 * max(n.z, 0.0);
  float sheen = pow(max(dot(n, normalize(v + vec3(0.0, 0.0, -1.0))), 0.0), 24.0);
  fragColour = vec4(min(base * (uAmbient + fill) + vec3(0.25 * sheen), vec3(1.0)), uAlpha);
  return;
#endif
#ifdef HIGH
  fragColour = vec4(toDisplay(litHigh(toLinear(base), n, v)), uAlpha);
  return;
#endif
  vec3 colour = uAmbient * base;
  for (int i = 0; i < 2; ++i) {
    vec3 to_light = uLightPos[i] - vWorldPos;
    float dist2 = dot(to_light, to_light);
    vec3 l = to_light * inversesqrt(dist2);
    float cone = smoothstep(uCosOuter, uCosInner, l.z);  // the lamps point straight down
    float falloff = min(uLightPos[i].z * uLightPos[i].z / dist2, 1.3);
    float diffuse = max(dot(n, l), 0.0);
    colour += cone * falloff * uLampGain * diffuse * base;
#if MATERIAL == 3 || MATERIAL == 5
    // Only the balls and the cue's varnish are glossy enough for a highlight worth its cost:
    // (n.h)^64 by squaring.
    float s = max(dot(n, normalize(l + v)), 0.0);
    s *= s; s *= s; s *= s; s *= s; s *= s; s *= s;
    colour += cone * uSpecular * (diffuse > 0.0 ? s : 0.0);
#endif
  }
  fragColour = vec4(min(colour, vec3(1.0)), uAlpha);
#endif
}
)";

/// The fragment source for one material: the version line, its MATERIAL define (and HIGH for the
/// high preset's variant), the body.
inline std::string withMaterial(int material, bool high = false) {
  return "#version 330 core\n#define MATERIAL " + std::to_string(material) + "\n" +
         (high ? "#define HIGH 1\n" : "") + kSceneFragment;
}

/// The shadow maps' depth pass: positions only.
inline constexpr const char* kDepthVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 uModel;
uniform mat4 uLightMatrix;
void main() { gl_Position = uLightMatrix * uModel * vec4(aPos, 1.0); }
)";

inline constexpr const char* kDepthFragment = R"(#version 330 core
void main() {}
)";

/// Text on a flat face (the Magic Eight Ball's answer triangle): the face lies in its local xy
/// plane; inside uTextBox (local x0, y0, x1, y1) the text texture's ink is drawn in near-white.
inline constexpr const char* kDecalVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 uModel;
uniform mat4 uViewProj;
out vec2 vLocal;
void main() {
  vLocal = aPos.xy;
  gl_Position = uViewProj * uModel * vec4(aPos, 1.0);
}
)";

inline constexpr const char* kDecalFragment = R"(#version 330 core
in vec2 vLocal;
uniform vec3 uColour;
uniform vec4 uTextBox;
uniform sampler2D uText;
out vec4 fragColour;
void main() {
  vec2 t = (vLocal - uTextBox.xy) / (uTextBox.zw - uTextBox.xy);
  float ink = 0.0;
  if (all(greaterThanEqual(t, vec2(0.0))) && all(lessThanEqual(t, vec2(1.0)))) {
    ink = texture(uText, vec2(t.x, 1.0 - t.y)).r;
  }
  fragColour = vec4(mix(uColour, vec3(0.92, 0.94, 1.0), ink), 1.0);
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
