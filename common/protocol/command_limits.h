// The ranges a shot command's values must lie in, on a given table.
#pragma once

#include <numbers>

#include "physics/shot_limits.h"

namespace pool::protocol {

/// The ranges a command's values must lie in. Defaults: docs/SIM-CONTRACT.md and a 9-ft table.
struct CommandLimits {
  double max_speed = physics::kMaxShotSpeed;      ///< m/s
  double max_elevation = physics::kMaxElevation;  ///< rad
  double miscue_limit = 0.5;                      ///< fraction of R
  double max_abs_yaw = 2 * std::numbers::pi;      ///< rad
  double half_length = 1.27;                      ///< playing surface, m (x)
  double half_width = 0.635;                      ///< playing surface, m (y)
};

}  // namespace pool::protocol
