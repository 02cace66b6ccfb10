// The two lamps over the table: where their lights hang, their spot cones and the light they
// give a point, their shades, and when a shade fades from a view (over the shot's points, or the
// eye up among the lamps).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <span>

#include <optional>
#include "client/render/camera.h"

#include "client/render/mesh.h"
#include "table/table_geometry.h"

namespace pool::render {

/// Light height above the slate, m (the shades' rims hang about 0.9 m over the bed, as over a
/// real table).
inline constexpr float kLampHeight = 0.95f;
/// Spot cone: full light inside the inner half-angle, none beyond the outer one, degrees. On the
/// felt: a full pool of 0.20 m radius fading out by 0.98 m under each lamp.
inline constexpr float kSpotInnerDeg = 12.0f;
inline constexpr float kSpotOuterDeg = 46.0f;
/// The high preset's cones, in linear light: full light within 0.25 m of the foot of a lamp,
/// none beyond 0.80 m, so that the felt midway between the lamps gets a quarter of a lamp's
/// light from each and the pools stand out as a real table's do.
inline constexpr float kHighSpotInnerDeg = 15.0f;
inline constexpr float kHighSpotOuterDeg = 40.0f;
/// A lamp's diffuse light on a surface facing it at its own height below it (share of albedo).
inline constexpr float kLampGain = 0.62f;
/// The shade: an enamel cone around the light, its rim this far below it and this wide, m.
inline constexpr float kShadeRimBelow = 0.03f;
inline constexpr float kShadeRadius = 0.20f;
/// A sphere around the light holding the whole shade (its disc in a view), m.
inline constexpr float kShadeBound = 0.23f;
/// A shade is gone from a view while its disc comes within this many pixels of a point it must
/// not hide, and fades in over the next kClearFade of its own radius farther.
inline constexpr float kClearMargin = 12.0f;
inline constexpr float kClearFade = 0.5f;

/// The two light positions, over the head and foot halves of the table (table frame, m).
std::array<glm::vec3, 2> lampPositions(const pool::table::TableGeometry& geometry);

/// The light a lamp at `lamp` gives a surface at `point` with unit normal `normal` (share of the
/// albedo, as the scene shader computes it: cone × cos(incidence) × (height / distance)²).
float lampLight(glm::vec3 lamp, glm::vec3 point, glm::vec3 normal);

/// The disc the shade round `lamp` covers at most in a width × height view (its bounding sphere's):
/// its centre in pixels from the top-left, its radius in pixels, and the distance from the eye
/// to the shade's centre, m. Nothing when it lies behind the eye; a radius over the view's
/// diagonal when the eye is inside the sphere.
struct ShadeDisc {
  glm::vec2 centre{0.0f};
  float radius = 0.0f;
  float distance = 0.0f;
};
std::optional<ShadeDisc> shadeDisc(const Camera& camera, int width, int height, glm::vec3 lamp);

/// How opaque the lamp is drawn in that view, 0–1: drawn whole over the table and the hall, it
/// fades only where its shade would hide a point of `keep_clear` (the shot's cue ball, object
/// ball and pocket: each farther from the eye than the shade, its pixel within kClearMargin of
/// the shade's disc), and when the eye comes within about 0.4 m of a shade (gone by 0.38 m from
/// its centre, whole from 0.63 m). A view looking down steeper than 70° from over the lamps (the
/// overhead, the top scene: a plan of the table) has none.
float lampOpacity(const Camera& camera, int width, int height, glm::vec3 lamp,
                  std::span<const glm::vec3> keep_clear = {});

/// A shade around a light at the origin: an enamel cone (rim below the light) closed at its top,
/// and a cord up to the ceiling. Normals point out.
MeshData lampShade();
/// The bulb: a sphere of this radius at the light, m.
inline constexpr float kBulbRadius = 0.035f;

}  // namespace pool::render
