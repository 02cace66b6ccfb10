// The two lamps over the table: where their lights hang, their spot cones and the light they
// give a point, their shades, and how much of a view a shade may take before it fades.
#pragma once

#include <array>
#include <glm/glm.hpp>

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
/// A sphere around the light holding the whole shade (for coverage of the view), m.
inline constexpr float kShadeBound = 0.23f;
/// A lamp is fully drawn while its shade covers less than this share of the view, and gone once
/// it covers kFadeOut.
inline constexpr float kFadeIn = 0.015f;
inline constexpr float kFadeOut = 0.03f;

/// The two light positions, over the head and foot halves of the table (table frame, m).
std::array<glm::vec3, 2> lampPositions(const pool::table::TableGeometry& geometry);

/// The light a lamp at `lamp` gives a surface at `point` with unit normal `normal` (share of the
/// albedo, as the scene shader computes it: cone × cos(incidence) × (height / distance)²).
float lampLight(glm::vec3 lamp, glm::vec3 point, glm::vec3 normal);

/// The share of a width × height view that the shade around `lamp` covers at most (its bounding
/// sphere's disc; 0 behind the camera).
float shadeCoverage(const Camera& camera, int width, int height, glm::vec3 lamp);

/// How opaque the lamp is drawn in that view, 0–1: faded as its shade would take more than
/// kFadeIn of the view, and when the eye is up among the lamps (looking down past them).
float lampOpacity(const Camera& camera, int width, int height, glm::vec3 lamp);

/// A shade around a light at the origin: an enamel cone (rim below the light) closed at its top,
/// and a cord up to the ceiling. Normals point out.
MeshData lampShade();
/// The bulb: a sphere of this radius at the light, m.
inline constexpr float kBulbRadius = 0.035f;

}  // namespace pool::render
