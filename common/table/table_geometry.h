// Collision geometry of a table: cushion nose lines, pocket holes and the triangle mesh, loaded
// through assimp.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"
#include "table/table_spec.h"

namespace pool::table {

/// A straight piece of cushion nose (the line where a ball touches a cushion), at the nose height
/// above the slate. Table frame, metres.
struct NoseSegment {
  std::string name;        ///< rail (head, foot, head_left, ...) or jaw (jaw_foot_left_corner, ...)
  Eigen::Vector2d a, b;    ///< end points in the table plane
  Eigen::Vector2d normal;  ///< unit, horizontal, pointing to the side a ball may be on
};

/// The hole in the slate under a pocket: a ball whose centre passes over it loses support.
struct PocketHole {
  std::string name;  ///< head_left_corner, left_side, foot_left_corner, head_right_corner, ...
  Eigen::Vector2d centre;  ///< table plane, m
  double radius = 0.0;     ///< m
};

/// Triangles of one named part of the table (slate, cushion_*, jaw_*, pocket_*, trough, rail, ...).
struct MeshPart {
  std::string name;
  std::vector<Eigen::Vector3d> vertices;  ///< table frame, m
  std::vector<std::array<std::uint32_t, 3>>
      triangles;  ///< indices into vertices, counter-clockwise seen from outside
};

/// What the physics collides with. Built from the spec by `buildTableGeometry`, written to an OBJ
/// by the table generator, and read back through assimp by `loadTableGeometry`.
struct TableGeometry {
  std::string name;                ///< the spec's name (written in the OBJ header)
  double length = 0.0;             ///< playing surface along x, m
  double width = 0.0;              ///< playing surface along y, m
  double nose_height = 0.0;        ///< cushion nose above the slate (the spec's cushion_height), m
  std::vector<NoseSegment> noses;  ///< 6 rails + 2 jaws per pocket
  std::vector<PocketHole> holes;   ///< 6
  std::vector<MeshPart> parts;     ///< triangle mesh, for ODE trimesh collisions and rendering
  double trough_z = 0.0;           ///< height of the trough floor (negative: under the slate), m
};

/// Computes the geometry from a spec (pure; no files).
TableGeometry buildTableGeometry(const TableSpec& spec);

/// Writes the geometry as a Wavefront OBJ: one `o` object per part (triangles), nose segments as
/// `l` lines in objects `nose_<name>`, pocket holes as closed `l` loops in objects `hole_<name>`.
/// The output is byte-identical for the same spec.
std::string toObj(const TableGeometry& geometry);

/// Loads the spec's collision mesh through assimp and rebuilds the geometry from it.
Result<TableGeometry> loadTableGeometry(const TableSpec& spec);

}  // namespace pool::table
