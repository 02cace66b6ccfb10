// The loudness and brightness laws of the table's sounds.
#include "client/audio/impact_law.h"

#include <algorithm>
#include <cmath>

namespace pool::audio {

const char* toString(SoundKind kind) {
  switch (kind) {
    case SoundKind::CueStrike:
      return "cue_strike";
    case SoundKind::BallClick:
      return "ball_click";
    case SoundKind::CushionThump:
      return "cushion_thump";
    case SoundKind::PocketDrop:
      return "pocket_drop";
  }
  return "unknown";
}

double ImpactLaw::amplitude(double speed) const {
  // NaN and anything under the floor are silent.
  if (!(speed >= floor) || speed <= 0.0) return 0.0;
  return ref_amplitude * std::pow(std::min(speed, cap) / ref_speed, exponent);
}

double ImpactLaw::brightness(double speed) const {
  if (!(speed > 0.0)) return 0.7;
  return std::clamp(std::pow(std::min(speed, cap) / ref_speed, 0.2), 0.7, 1.4);
}

const ImpactLaw& ImpactLaws::of(SoundKind kind) const {
  switch (kind) {
    case SoundKind::CueStrike:
      return strike;
    case SoundKind::BallClick:
      return click;
    case SoundKind::CushionThump:
      return thump;
    case SoundKind::PocketDrop:
      return pocket;
  }
  return click;
}

}  // namespace pool::audio
