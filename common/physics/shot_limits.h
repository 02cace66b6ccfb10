// The ranges a cue shot's values may take: the one home of the numbers that the physics' check
// (validateShot), the protocol's command limits, the controls, the bot and the cue's drawing use.
#pragma once

#include <numbers>

namespace pool::physics {

/// The fastest cue (or ball) speed a shot may ask for, m/s (docs/SIM-CONTRACT.md: a power break
/// is about 11 m/s; nothing a player makes exceeds 12).
inline constexpr double kMaxShotSpeed = 12.0;

/// The steepest cue elevation, degrees: 90° (straight down) has no heading, so a shot stops short.
inline constexpr double kMaxElevationDeg = 89.0;

/// kMaxElevationDeg in radians.
inline constexpr double kMaxElevation = kMaxElevationDeg * std::numbers::pi / 180.0;

}  // namespace pool::physics
