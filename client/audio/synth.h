// Procedural synthesis of the table's sounds (modal ringing, noise bursts, a pocket's rattle).
#pragma once

#include <vector>

#include "client/audio/impact_law.h"

namespace pool::audio {

constexpr int kDefaultSampleRate = 48000;  ///< Hz

/// One mono sound of `kind` at `rate` Hz, normalised to an RMS of 1 over its whole length.
/// `brightness` scales the frequencies of the ringing modes (1: a 2 m/s impact); `variant`
/// (0, 1, 2, ...) detunes the modes and moves the rattle a little, so that repeated impacts do not
/// sound identical. Deterministic: the same arguments give the same samples, bit for bit.
std::vector<float> synthesize(SoundKind kind, double brightness, int variant,
                              int rate = kDefaultSampleRate);

/// The length of a kind's sound, s.
double soundLength(SoundKind kind);

}  // namespace pool::audio
