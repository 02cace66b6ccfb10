// Internal to pool_table: where rails, jaw facings and pocket holes lie for a spec, plus mesh
// constants.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "table/table_spec.h"

namespace pool::table::detail {

inline constexpr int kHoleSegments = 48;     ///< segments of each hole's polygonal circle
inline constexpr double kTileMargin = 0.02;  ///< slate ring around a hole, beyond its radius, m
inline constexpr double kEdgeMargin =
    0.002;  ///< least slate between a hole and the slate's outer edge, m
inline constexpr double kTroughHeadZ = -0.15;  ///< trough floor at the head end, m
inline constexpr double kTroughSlope = 0.02;   ///< trough floor drop per metre toward the foot
inline constexpr double kLinerBelowSlate =
    0.05;  ///< pocket liner reaches this far under the slate, m
inline constexpr double kCushionTopAboveNose = 0.005;  ///< cushion top above the nose line, m

/// One pocket: its reference point on the nose lines, the outward direction and its hole.
struct PocketLayout {
  std::string name;
  bool corner = false;
  Eigen::Vector2d reference;  ///< corner: where the two rail nose lines meet; side: (0, ±W/2)
  Eigen::Vector2d outward;    ///< unit, away from the table centre (diagonal or ±y)
  Eigen::Vector2d hole_centre;
  double hole_radius = 0.0;
  double jaw_angle_deg = 0.0;
};

/// A rail end at a corner of a table without pockets, where two cushions meet.
inline constexpr int kNoPocket = -1;

/// One rail's nose line from jaw point to jaw point (a table without pockets: corner to corner);
/// normal = left perpendicular of (b − a).
struct RailLayout {
  std::string name;
  Eigen::Vector2d a, b;
  Eigen::Vector2d normal;  ///< unit, into the table
  int pocket_a = 0;        ///< pocket at end a (index into pocketLayouts), or kNoPocket
  int pocket_b = 0;        ///< pocket at end b
};

/// One jaw facing, from the rail's jaw point P outward to the back of the cushion E.
struct JawLayout {
  int pocket = 0;
  int rail = 0;
  Eigen::Vector2d point;    ///< P: where the rail's nose ends
  Eigen::Vector2d end;      ///< E: where the facing reaches the back of the cushion
  Eigen::Vector2d along;    ///< unit, the rail direction at P pointing toward the pocket
  Eigen::Vector2d outward;  ///< unit, away from the table (minus the rail normal)
  Eigen::Vector2d facing;   ///< unit, P → E
  Eigen::Vector2d normal;   ///< unit, into the pocket opening
  double turn = 0.0;  ///< 180° − jaw angle, rad: the facing's turn from `along` toward `outward`
};

/// Left perpendicular (rotated +90° about +z).
inline Eigen::Vector2d leftPerp(const Eigen::Vector2d& v) {
  return {-v.y(), v.x()};
}

std::vector<PocketLayout> pocketLayouts(const TableSpec& spec);
std::vector<RailLayout> railLayouts(const TableSpec& spec);
/// Two facings per pocket, in pocket order, then in rail order within a pocket.
std::vector<JawLayout> jawLayouts(const TableSpec& spec);

/// Outer half-extents of the slate (playing surface plus cushions and rails), m.
Eigen::Vector2d slateHalfExtent(const TableSpec& spec);

/// The axis-aligned slate tile around a pocket hole: [min, max], reaching the slate's outer edges.
struct Tile {
  Eigen::Vector2d min, max;
};
Tile holeTile(const TableSpec& spec, const PocketLayout& pocket);

}  // namespace pool::table::detail
