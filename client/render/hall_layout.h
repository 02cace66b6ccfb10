// Where the pool hall's pieces stand around the table (table frame: origin at the slate's centre,
// +x toward the foot, z up, metres): floor, walls, ceiling, the table's apron, and what hangs on
// the walls. Shared by the hall's generator, the renderer and the tests.
#pragma once

#include <array>
#include <glm/glm.hpp>

namespace pool::render::hall {

/// The floor, 79 cm under the slate (a pool table's bed height).
inline constexpr float kFloorZ = -0.79f;
/// The ceiling, 3 m above the floor.
inline constexpr float kCeilingZ = kFloorZ + 3.0f;
/// The walls stand at x = ±kHalfX and y = ±kHalfY.
inline constexpr float kHalfX = 4.6f;
inline constexpr float kHalfY = 3.4f;
/// Wood panelling on the walls up to this height; wallpaper above.
inline constexpr float kWainscotTop = kFloorZ + 1.05f;
/// The table's apron (the wooden skirt under the rails) ends this low.
inline constexpr float kApronBottom = -0.17f;

/// Something on a wall: its centre on the wall's face, its width along the wall and its height,
/// and the wall's inward normal.
struct WallPiece {
  const char* name;
  glm::vec3 centre;
  glm::vec2 size;
  glm::vec3 inward;
};

/// The cue rack, the scoreboard and the framed pictures.
inline constexpr std::array<WallPiece, 6> kWallPieces{{
    {"cue_rack", {kHalfX, -1.3f, 0.30f}, {1.0f, 1.5f}, {-1.0f, 0.0f, 0.0f}},
    {"scoreboard", {kHalfX, 1.2f, 0.62f}, {1.5f, 0.36f}, {-1.0f, 0.0f, 0.0f}},
    {"picture", {-1.6f, kHalfY, 0.95f}, {0.9f, 0.65f}, {0.0f, -1.0f, 0.0f}},
    {"picture", {1.6f, kHalfY, 0.95f}, {0.9f, 0.65f}, {0.0f, -1.0f, 0.0f}},
    {"picture", {0.0f, -kHalfY, 0.95f}, {1.1f, 0.75f}, {0.0f, 1.0f, 0.0f}},
    {"picture", {-kHalfX, 0.0f, 0.95f}, {1.0f, 0.7f}, {1.0f, 0.0f, 0.0f}},
}};

/// Bar stools along the long sides: their seats' centres (the seat top is kStoolSeatZ).
inline constexpr std::array<glm::vec2, 4> kStools{
    {{-2.3f, -2.0f}, {2.3f, -2.0f}, {-2.3f, 2.0f}, {2.3f, 2.0f}}};
inline constexpr float kStoolSeatZ = kFloorZ + 0.76f;
inline constexpr float kStoolSeatRadius = 0.19f;

}  // namespace pool::render::hall
