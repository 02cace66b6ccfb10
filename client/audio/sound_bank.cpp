// Synthesises the bank of template sounds and picks one for each cue.
#include "client/audio/sound_bank.h"

#include <algorithm>
#include <cmath>

namespace pool::audio {

SoundBank::SoundBank(int rate) : rate_(rate) {
  sounds_.reserve(static_cast<std::size_t>(kSoundKinds * kBands * kVariants));
  for (int k = 0; k < kSoundKinds; ++k) {
    const auto kind = static_cast<SoundKind>(k);
    for (int band = 0; band < kBands; ++band) {
      for (int v = 0; v < kVariants; ++v) {
        // The pocket drop's sound does not depend on speed: one band, shared by all.
        const bool banded = kind != SoundKind::PocketDrop || band == 0;
        sounds_.push_back(banded ? synthesize(kind, bandBrightness(band), v, rate)
                                 : std::vector<float>{});
      }
    }
  }
}

double SoundBank::bandBrightness(int band) {
  return 0.7 * std::pow(2.0, static_cast<double>(band) / (kBands - 1));
}

int SoundBank::bandOf(double brightness) {
  if (!(brightness > 0.0)) return 0;
  const double x = std::log2(brightness / 0.7) * (kBands - 1);
  return std::clamp(static_cast<int>(std::lround(x)), 0, kBands - 1);
}

std::span<const float> SoundBank::pick(const SoundCue& cue) const {
  const int band = cue.kind == SoundKind::PocketDrop ? 0 : bandOf(cue.brightness);
  const auto millis = static_cast<long long>(cue.t * 1000.0);
  const int variant = static_cast<int>((std::abs(cue.ball) + std::llabs(millis)) % kVariants);
  const auto index = (static_cast<int>(cue.kind) * kBands + band) * kVariants + variant;
  return sounds_[static_cast<std::size_t>(index)];
}

}  // namespace pool::audio
