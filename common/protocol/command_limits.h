// The ranges a shot command's values must lie in, on a given table.
#pragma once

#include <numbers>

namespace pool::protocol {

/// The ranges a command's values must lie in. Defaults: docs/SIM-CONTRACT.md and a 9-ft table.
struct CommandLimits {
  double max_speed = 12.0;                               ///< m/s
  double max_elevation = 89.0 * std::numbers::pi / 180;  ///< rad
  double miscue_limit = 0.5;                             ///< fraction of R
  double max_abs_yaw = 2 * std::numbers::pi;             ///< rad
  double half_length = 1.27;                             ///< playing surface, m (x)
  double half_width = 0.635;                             ///< playing surface, m (y)
};

}  // namespace pool::protocol
