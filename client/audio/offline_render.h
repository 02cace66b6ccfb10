// A shot's sound mixed offline, sample-exact, through the same bank and mixer as the board.
#pragma once

#include <vector>

#include "client/audio/mixer.h"
#include "client/audio/sound_bank.h"
#include "client/audio/sound_cue.h"

namespace pool::audio {

/// The mixed samples and what the mixer did.
struct Rendering {
  std::vector<float> samples;  ///< mono, at the bank's rate
  MixerStats stats;
};

/// Mixes every cue at its own sample (cues sorted by time), from t = 0 to the last cue plus
/// `tail` s. The mixer's rate is taken from the bank.
Rendering renderCues(const std::vector<SoundCue>& cues, const SoundBank& bank,
                     MixerOptions options = {}, double tail = 1.2);

}  // namespace pool::audio
