// The ranges a shot command's values must lie in, on a given table.
#pragma once

#include "physics/shot_limits.h"

namespace pool::protocol {

/// The ranges a command's values must lie in: the shot's (checked by physics::checkShotRange)
/// and the playing surface's, for a placed cue ball. Defaults: docs/SIM-CONTRACT.md and a 9-ft
/// table.
struct CommandLimits : physics::ShotRanges {
  double half_length = 1.27;  ///< playing surface, m (x)
  double half_width = 0.635;  ///< playing surface, m (y)
};

}  // namespace pool::protocol
