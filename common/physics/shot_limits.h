// The ranges a cue shot's values may take, and the one check of them (checkShotRange).
#pragma once

#include <cstdint>
#include <numbers>

#include "core/check.h"

namespace pool::physics {

/// The fastest cue (or ball) speed a shot may ask for, m/s (docs/SIM-CONTRACT.md: a power break
/// is about 11 m/s; nothing a player makes exceeds 12).
inline constexpr double kMaxShotSpeed = 12.0;

/// The steepest cue elevation, degrees: 90° (straight down) has no heading, so a shot stops short.
inline constexpr double kMaxElevationDeg = 89.0;

/// kMaxElevationDeg in radians.
inline constexpr double kMaxElevation = kMaxElevationDeg * std::numbers::pi / 180.0;

/// The largest tip offset before a miscue, fraction of R (Shepard, "Amateur Physics for the
/// Amateur Pool Player": about half the radius); a table's physics may set its own.
inline constexpr double kMiscueLimit = 0.5;

/// How far past an angle's or the tip offset's limit a value still counts as on it: a limit met
/// after a square root or a conversion from degrees (0.3, 0.4 against 0.5; 89° in radians) stays
/// legal.
inline constexpr double kRangeTolerance = 1e-12;

/// The ranges one table allows; the defaults are the limits above.
struct ShotRanges {
  double max_speed = kMaxShotSpeed;           ///< m/s
  double max_elevation = kMaxElevation;       ///< rad
  double miscue_limit = kMiscueLimit;         ///< fraction of R
  double max_abs_yaw = 2 * std::numbers::pi;  ///< rad
};

/// A shot's values as the player sets them. Angles in radians.
struct ShotValues {
  double speed = 0.0;  ///< m/s
  double elevation = 0.0;
  double tip_side = 0.0;  ///< fraction of R
  double tip_height = 0.0;
  double yaw = 0.0;
};

/// Why a shot's values are refused, in the order they are checked.
enum class ShotProblem : std::uint8_t {
  None,
  NonFinite,            ///< a value is NaN or infinite
  SpeedOutOfRange,      ///< not in (0, max_speed]
  ElevationOutOfRange,  ///< not in [0, max_elevation]
  TipOutOfRange,        ///< sqrt(side² + height²) beyond the miscue limit
  YawOutOfRange,        ///< |yaw| beyond max_abs_yaw
};

const char* toString(ShotProblem problem);  ///< snake_case, e.g. "speed_out_of_range"

/// Checks `values` against `ranges`; the sentence names the field and its range ("speed: must be
/// in (0, 12] m/s"). `with_speed` false skips the speed (an aim, which has no speed yet).
Check<ShotProblem> checkShotRange(const ShotValues& values, const ShotRanges& ranges = {},
                                  bool with_speed = true);

}  // namespace pool::physics
