// How hard an impact sounds: loudness and brightness of each kind of table sound from its speed.
#pragma once

#include <cstdint>

namespace pool::audio {

/// The table's sounds.
enum class SoundKind : std::uint8_t {
  CueStrike,     ///< the cue tip hits the cue ball
  BallClick,     ///< ball hits ball: short, bright, decaying
  CushionThump,  ///< ball hits a cushion, a jaw or lands on the slate: lower, damped
  PocketDrop,    ///< ball drops into a pocket: a rattle, then a roll in the trough
};

constexpr int kSoundKinds = 4;
const char* toString(SoundKind kind);

/// The loudness law of one kind of impact. The sound's peak pressure follows the peak contact
/// force, which for a Hertzian contact grows as v^(6/5); the contact time shrinks as v^(-1/5),
/// which moves the ringing modes' excitation (the brightness) up by the same factor:
///   amplitude(v) = ref_amplitude · (min(v, cap) / ref_speed)^exponent   for v ≥ floor, else 0
///   brightness(v) = clamp((min(v, cap) / ref_speed)^(1/5), 0.7, 1.4)
/// Amplitude is the RMS of the sound over its whole length, in full-scale units (±1 = full scale).
struct ImpactLaw {
  double floor = 0.05;          ///< m/s: slower impacts make no sound
  double cap = 8.0;             ///< m/s: faster impacts sound like this one
  double ref_speed = 2.0;       ///< m/s: the speed that sounds at ref_amplitude
  double ref_amplitude = 0.01;  ///< RMS at ref_speed
  double exponent = 1.2;        ///< amplitude ∝ speed^exponent (Hertz: 6/5)

  /// RMS amplitude of an impact at `speed` m/s; 0 under the floor (and for NaN).
  double amplitude(double speed) const;
  /// Frequency scale of the sound's modes (1 at ref_speed).
  double brightness(double speed) const;
};

/// The laws of the four kinds, tuned so that one impact at a break's speeds peaks near half scale.
struct ImpactLaws {
  // The sounds' peaks are about 8 times their RMS: a capped click peaks near 0.5, a break's
  // strike near 0.6, and a burst of them is left to the mixer's limiter.
  ImpactLaw strike{0.1, 10.0, 3.0, 0.023, 1.2};
  ImpactLaw click{0.03, 8.0, 2.0, 0.012, 1.2};
  ImpactLaw thump{0.05, 6.0, 2.0, 0.03, 1.2};
  /// A ball drops about 0.1 m into the liner: it lands at √(2 g h) ≈ 1.4 m/s whatever its speed
  /// on the cloth (the event log carries none for pocket drops).
  ImpactLaw pocket{0.0, 3.0, 1.4, 0.065, 1.2};
  double pocket_fall_speed = 1.4;  ///< m/s, the speed a pocket drop sounds at

  const ImpactLaw& of(SoundKind kind) const;
};

}  // namespace pool::audio
