// How each ball looks in the plot: the usual colours, stripes for 9-15, a white cue ball; a carom
// or snooker table's own set.
#pragma once

#include <string>

#include "table/table_spec.h"

namespace pool::scenario {

/// A ball's colours in the plot.
struct BallStyle {
  std::string colour;    ///< SVG colour of the ball and its path
  bool striped = false;  ///< 9-15: path dashed, ball drawn as a ring
  bool cue = false;      ///< the cue ball: white with a dark outline
};

/// 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon, 8 black, 9-15 as 1-7 striped, 0
/// white.
BallStyle ballStyle(int id);

/// The ball's style on `spec`: a snooker table's set (1-15 red, 16-21 yellow, green, brown, blue,
/// pink, black), a carom table's (0 white, 1 yellow, 2 red), else the pool set above.
BallStyle ballStyle(int id, const table::TableSpec& spec);

}  // namespace pool::scenario
