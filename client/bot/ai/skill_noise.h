// The bot's human error: seeded aim and speed noise that shrinks to nothing at skill 1.
#pragma once

#include <cstdint>

#include "core/split_mix64.h"
#include "physics/cue_strike.h"
#include "physics/shot_limits.h"

namespace pool::bot {

/// A seeded PRNG (SplitMix64) whose sequence is fixed by its seed on every platform.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : rng_(seed) {}
  /// The next 64 random bits.
  std::uint64_t next();
  /// Uniform in [0, 1).
  double uniform();
  /// Standard normal (Box–Muller), clamped to ±3.
  double gaussian();

 private:
  SplitMix64 rng_;
};

/// Standard deviations of the noise at skill 0; they shrink linearly to 0 at skill 1.
inline constexpr double kYawSigmaAtZero = 0.03;    ///< rad (≈ 1.7°)
inline constexpr double kSpeedSigmaAtZero = 0.25;  ///< relative

/// Aim and speed error of a player of `skill` (0..1, clamped; 1 = none).
class SkillNoise {
 public:
  SkillNoise(double skill, std::uint64_t seed);

  /// `shot` with its yaw moved by at most 3 yaw sigmas and its speed scaled by at most 1 ± 3
  /// speed sigmas (never above `max_speed`, m/s).
  physics::CueShot apply(const physics::CueShot& shot, double max_speed = physics::kMaxShotSpeed);

  double yawSigma() const { return yaw_sigma_; }      ///< rad
  double speedSigma() const { return speed_sigma_; }  ///< relative

 private:
  double yaw_sigma_;
  double speed_sigma_;
  Rng rng_;
};

}  // namespace pool::bot
