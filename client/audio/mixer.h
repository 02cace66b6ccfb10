// The voice mixer: a fixed set of voices, voice stealing, a peak limiter and a soft clipper.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pool::audio {

struct MixerOptions {
  int voices = 24;        ///< sounds at once; more steal the quietest (a break: 100+ clicks)
  int rate = 48000;       ///< Hz
  float master = 1.0f;    ///< gain applied to the sum
  float limit = 1.0f;     ///< the limiter keeps the gained sum's peaks at or under this
  double release = 0.08;  ///< s, the limiter's release time constant
  float knee = 0.7f;      ///< the soft clipper is linear under this, then bends toward 1
};

/// What the mixer did so far.
struct MixerStats {
  std::uint64_t started = 0;  ///< sounds started (stolen voices included)
  std::uint64_t stolen = 0;   ///< sounds that took the voice of a quieter one
  std::uint64_t dropped = 0;  ///< sounds not started: every voice was louder
  int max_active = 0;         ///< the most voices sounding at once
  std::uint64_t limited = 0;  ///< samples the limiter turned down
  float peak_in = 0.0f;       ///< largest |sum| before the limiter
  float peak_out = 0.0f;      ///< largest |output|
};

/// Mixes mono voices into blocks of samples. start() and mix() allocate nothing and take no
/// lock; the sounds' samples must outlive their voices (they come from a SoundBank).
class Mixer {
 public:
  explicit Mixer(const MixerOptions& options = {});

  /// Starts `sound` at `gain` after `delay` frames of the next mix() call. When every voice is
  /// busy it takes the voice with the least remaining loudness, if that is quieter than `gain`.
  void start(std::span<const float> sound, float gain, std::uint32_t delay = 0);

  /// Writes `out.size()` mixed samples, every one in (-1, 1).
  void mix(std::span<float> out);

  /// Silences every voice at once.
  void stopAll();

  int active() const;
  const MixerStats& stats() const { return stats_; }
  const MixerOptions& options() const { return options_; }

 private:
  struct Voice {
    const float* data = nullptr;
    std::uint32_t length = 0;
    std::uint32_t pos = 0;
    std::uint32_t delay = 0;
    float gain = 0.0f;
    bool busy() const { return data != nullptr; }
    /// The voice's gain weighted by how much of it is left.
    float remaining() const;
  };

  MixerOptions options_;
  std::vector<Voice> voices_;
  float envelope_ = 0.0f;  ///< the limiter's peak follower
  float release_coef_;
  MixerStats stats_;
};

/// The soft clipper: linear up to `knee`, then a tanh bend that never reaches ±1.
float softClip(float x, float knee);

}  // namespace pool::audio
