// The baulk line, the D and the six colours' spots of a snooker table, from its spec's marks.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "table/table_spec.h"

namespace pool::table {

/// A snooker table's marks in the table frame (origin at the centre, +x toward the top cushion,
/// the head end being baulk). Official Rules of Snooker, Section 1, 1(d)-(f).
struct SnookerSpots {
  double baulk_x = 0.0;   ///< x of the baulk line
  double d_radius = 0.0;  ///< the D: a semicircle in baulk about the brown spot
  Eigen::Vector2d yellow, green, brown, blue, pink, black;
};

/// The marks of a table whose spec has `snooker_marks`; none for other tables. Viewed from the
/// baulk end, yellow is on the right of the D (−y) and green on the left (+y); the blue is at the
/// centre, the pink midway between the centre and the face of the top cushion.
std::optional<SnookerSpots> snookerSpotsFor(const TableSpec& spec);

/// Whether a ball's centre is in the D (on its line or inside it), where the cue ball is played
/// from hand.
bool inTheD(const SnookerSpots& spots, const Eigen::Vector2d& pos);

}  // namespace pool::table
