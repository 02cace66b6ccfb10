// Table specification as data: playing surface, cushions, pockets and coefficients, read from JSON.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/result.h"
#include "table/contact_models.h"
#include "table/physics_params.h"

namespace pool::table {

/// One kind of pocket (all four corners share one, both sides another).
struct PocketSpec {
  double mouth = 0.0;  ///< distance between the two jaw points (nose-line ends), m
  double jaw_angle_deg =
      0.0;  ///< angle between the rail's nose line and the jaw facing (142 corner, 104 side)
  double hole_radius = 0.0;  ///< radius of the hole in the slate, m
  double hole_offset =
      0.0;  ///< hole centre behind the pocket's reference point, m (see table_geometry.h)
};

/// The marks of a snooker table (Rules of Snooker, Section 1, 1(d)-(f)), m: the baulk line from
/// the face of the bottom (head) cushion, the D's radius about the middle of the baulk line, and
/// the black spot from the face of the top (foot) cushion. The other spots follow from these and
/// the playing surface (table/snooker_spots.h).
struct SnookerMarks {
  double baulk_line = 0.0;
  double d_radius = 0.0;
  double black_spot = 0.0;
};

/// A whole table. The playing surface is the rectangle between the cushion noses.
struct TableSpec {
  std::string name;                ///< e.g. "wpa-9ft"
  double length = 2.54;            ///< playing surface along x, m
  double width = 1.27;             ///< playing surface along y, m
  double cushion_width = 0.05;     ///< nose to the back of the cushion rubber, m
  double rail_width = 0.10;        ///< wooden rail beyond the cushion, m
  double slate_thickness = 0.025;  ///< m
  bool pockets = true;             ///< false: a carom table, four whole cushions and no pocket
  PocketSpec corner;               ///< unused without pockets
  PocketSpec side;                 ///< unused without pockets
  std::optional<SnookerMarks> snooker_marks;  ///< a snooker table's baulk line, D and spots
  PhysicsParams params;
  ContactModels models;                  ///< the contact model of each pair (`models` in the spec)
  std::filesystem::path collision_mesh;  ///< absolute path of the collision mesh (OBJ)
  std::filesystem::path
      render_mesh;  ///< absolute path of the render mesh; may equal collision_mesh
};

/// True for a spec's name as a peer may send it: 1–32 of [a-z0-9-] (never a path, so a name a
/// sample carries can only name a table of assets/tables).
bool isSpecName(const std::string& name);

/// Loads a spec by name ("wpa-9ft", "wpa-8ft", "wpa-7ft", "snooker-12ft", "carom-match":
/// assets/tables/<name>.json) or by path
/// to a JSON file. Failure gives a one-line reason naming the field.
Result<TableSpec> loadTableSpec(const std::string& nameOrPath);

/// Parses a spec's JSON text. `source` names the text in messages (its file's path), mesh paths
/// are relative to `spec_dir`, and `default_name` is the spec's name when the text gives none.
Result<TableSpec> parseTableSpec(const std::string& json_text, const std::string& source,
                                 const std::filesystem::path& spec_dir,
                                 const std::string& default_name);

}  // namespace pool::table
