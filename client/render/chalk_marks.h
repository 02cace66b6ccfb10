// A snooker table's chalk marks (baulk line, D, six spots) as the window and the web page draw
// them.
#pragma once

#include "table/snooker_spots.h"

namespace pool::render {

/// A snooker table's chalk marks as the marked felt (shaders::kMarkedFelt) draws them: the
/// baulk line across the bed, the D (a semicircle about the brown spot, on the baulk side) and
/// the six colours' spots, in chalk-white (chalkColour()) mixed into the felt.
struct ChalkMarks {
  static constexpr float kLineWidth = 0.0025f;   ///< the baulk line's and the D's, m
  static constexpr float kSpotRadius = 0.0045f;  ///< each spot's, m
  static constexpr float kStrength = 0.7f;       ///< the chalk's share where a mark covers
  pool::table::SnookerSpots spots;
  float bed_half_width = 0.0f;  ///< the baulk line runs across the bed, |y| up to this, m
};

}  // namespace pool::render
