// The synthesised sounds a board plays, made once: each kind in a few brightness bands and
// variants.
#pragma once

#include <span>
#include <vector>

#include "client/audio/sound_cue.h"
#include "client/audio/synth.h"

namespace pool::audio {

/// Every template sound, synthesised at construction (tens of milliseconds of work, a few MB).
/// Playing a cue then only reads samples: nothing is synthesised or allocated on the way out.
class SoundBank {
 public:
  static constexpr int kBands = 6;     ///< brightness bands, geometric over [0.7, 1.4]
  static constexpr int kVariants = 3;  ///< detuned versions of each band

  explicit SoundBank(int rate = kDefaultSampleRate);

  /// The template for a cue: its kind, the band nearest its brightness, a variant chosen from
  /// its ball and time (so repeated impacts differ, and the same log always sounds the same).
  std::span<const float> pick(const SoundCue& cue) const;

  /// The brightness of band `band` (0 .. kBands-1).
  static double bandBrightness(int band);
  /// The band nearest a brightness.
  static int bandOf(double brightness);

  int rate() const { return rate_; }

 private:
  int rate_;
  std::vector<std::vector<float>> sounds_;  ///< [(kind · kBands + band) · kVariants + variant]
};

}  // namespace pool::audio
