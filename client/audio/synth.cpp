// The table's sounds built from damped modes and filtered noise, with a seeded generator.
#include "client/audio/synth.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/split_mix64.h"

namespace pool::audio {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Deterministic noise: the same seed, the same sounds on every machine.
class Noise {
 public:
  explicit Noise(std::uint64_t seed) : rng_(seed) {}
  /// Uniform in [-1, 1).
  double next() { return 2.0 * rng_.uniform() - 1.0; }

 private:
  SplitMix64 rng_;
};

/// One ringing mode of a struck body.
struct Mode {
  double freq;  ///< Hz
  double gain;
  double decay;  ///< s, time constant of the exponential decay
};

/// The buffer being built, with its rate.
struct Canvas {
  std::vector<double> s;
  double rate;
  double dt() const { return 1.0 / rate; }
};

/// Adds exponentially decaying sines, starting at `start` s.
void addModes(Canvas& c, double start, double scale, const Mode* modes, int count) {
  const auto first = static_cast<std::size_t>(start * c.rate);
  for (int m = 0; m < count; ++m) {
    const Mode& mode = modes[m];
    if (mode.freq >= c.rate * 0.45) continue;  // above Nyquist's margin: would alias
    for (std::size_t i = first; i < c.s.size(); ++i) {
      const double t = static_cast<double>(i - first) * c.dt();
      c.s[i] += scale * mode.gain * std::exp(-t / mode.decay) * std::sin(kTwoPi * mode.freq * t);
    }
  }
}

/// Adds a burst of low-passed noise (the contact's broadband transient) at `start` s.
void addBurst(Canvas& c, Noise& noise, double start, double gain, double decay, double cutoff) {
  const auto first = static_cast<std::size_t>(start * c.rate);
  const double alpha = 1.0 - std::exp(-kTwoPi * cutoff * c.dt());
  double y = 0.0;
  for (std::size_t i = first; i < c.s.size(); ++i) {
    const double t = static_cast<double>(i - first) * c.dt();
    const double env = std::exp(-t / decay);
    if (env < 1e-4) break;
    y += alpha * (noise.next() - y);
    c.s[i] += gain * env * y;
  }
}

/// Detunes a frequency by up to ±3 % for variant sounds.
double detune(Noise& noise) {
  return 1.0 + 0.03 * noise.next();
}

/// A struck body: its ringing modes (scaled by the brightness unless `fixed`) and the contact's
/// noise burst.
struct BodySpec {
  Mode modes[4];
  bool fixed[4];
  int count;
  struct {
    double gain, decay, cutoff;  ///< cutoff (Hz) scaled by the brightness
  } burst;
};

void strikeBody(Canvas& c, Noise& noise, double b, const BodySpec& body) {
  Mode modes[4];
  for (int m = 0; m < body.count; ++m) {
    modes[m] = body.modes[m];
    modes[m].freq *= (body.fixed[m] ? 1.0 : b) * detune(noise);
  }
  addModes(c, 0.0, 1.0, modes, body.count);
  addBurst(c, noise, 0.0, body.burst.gain, body.burst.decay, body.burst.cutoff * b);
}

// Phenolic resin rings high and briefly; the contact itself is a sub-millisecond tick.
constexpr BodySpec kBallClick{
    .modes = {{3600, 1.0, 0.009}, {5900, 0.6, 0.005}, {8300, 0.35, 0.003}},
    .fixed = {},
    .count = 3,
    .burst = {0.5, 0.0006, 6000}};
// The leather tip softens the hit: a mid "tock", the shaft's low body, a dull transient.
constexpr BodySpec kCueStrike{
    .modes = {{1100, 1.0, 0.012}, {2300, 0.5, 0.007}, {4100, 0.3, 0.004}, {320, 0.6, 0.015}},
    .fixed = {false, false, false, true},
    .count = 4,
    .burst = {0.6, 0.0015, 3000}};
// Rubber and wood: low, heavily damped modes, a muffled burst and a faint click of the ball.
constexpr BodySpec kCushionThump{
    .modes = {{95, 1.0, 0.035}, {170, 0.6, 0.025}, {260, 0.3, 0.015}, {3600, 0.12, 0.004}},
    .fixed = {},
    .count = 4,
    .burst = {0.8, 0.006, 800}};

void pocketDrop(Canvas& c, Noise& noise) {
  // The rattle: the ball bounces off the liner a few times, each hit softer and sooner.
  double at = 0.0;
  double gain = 1.0;
  double gap = 0.04 * (1.0 + 0.25 * noise.next());
  for (int hit = 0; hit < 4; ++hit) {
    const Mode modes[] = {{1800 * detune(noise), 1.0, 0.008},
                          {3100 * detune(noise), 0.5, 0.005},
                          {180 * detune(noise), 0.8, 0.02}};
    addModes(c, at, gain, modes, 3);
    addBurst(c, noise, at, 0.4 * gain, 0.001, 2500);
    at += gap;
    gap *= 0.75;
    gain *= 0.6;
  }
  // The roll in the trough: low rumble with a wobble, rising then fading away.
  const double roll_start = at + 0.03;
  const double roll_length = 0.7;
  const double alpha = 1.0 - std::exp(-kTwoPi * 300.0 * c.dt());
  const double r = std::exp(-std::numbers::pi * 60.0 * c.dt());
  const double cw = 2.0 * r * std::cos(kTwoPi * 220.0 * c.dt());
  double lp = 0.0, y1 = 0.0, y2 = 0.0;
  const auto first = static_cast<std::size_t>(roll_start * c.rate);
  for (std::size_t i = first; i < c.s.size(); ++i) {
    const double t = static_cast<double>(i - first) * c.dt();
    if (t > roll_length) break;
    const double env = std::sin(std::numbers::pi * t / roll_length);
    lp += alpha * (noise.next() - lp);
    const double y = lp + cw * y1 - r * r * y2;  // a resonance of the trough
    y2 = y1;
    y1 = y;
    c.s[i] += 0.02 * env * env * (1.0 + 0.5 * std::sin(kTwoPi * 11.0 * t)) * y;
  }
}

}  // namespace

double soundLength(SoundKind kind) {
  switch (kind) {
    case SoundKind::CueStrike:
      return 0.1;
    case SoundKind::BallClick:
      return 0.08;
    case SoundKind::CushionThump:
      return 0.2;
    case SoundKind::PocketDrop:
      return 1.0;
  }
  return 0.1;
}

std::vector<float> synthesize(SoundKind kind, double brightness, int variant, int rate) {
  Canvas c{std::vector<double>(static_cast<std::size_t>(soundLength(kind) * rate), 0.0),
           static_cast<double>(rate)};
  Noise noise(0x5EED0000ULL + static_cast<std::uint64_t>(kind) * 1000u +
              static_cast<std::uint64_t>(variant));
  switch (kind) {
    case SoundKind::CueStrike:
      strikeBody(c, noise, brightness, kCueStrike);
      break;
    case SoundKind::BallClick:
      strikeBody(c, noise, brightness, kBallClick);
      break;
    case SoundKind::CushionThump:
      strikeBody(c, noise, brightness, kCushionThump);
      break;
    case SoundKind::PocketDrop:
      pocketDrop(c, noise);
      break;
  }
  // A short fade-out so that the sound ends at zero, then RMS 1.
  const std::size_t fade =
      std::min<std::size_t>(c.s.size(), static_cast<std::size_t>(0.005 * rate));
  for (std::size_t k = 0; k < fade; ++k) {
    c.s[c.s.size() - 1 - k] *= static_cast<double>(k) / static_cast<double>(fade);
  }
  double sum = 0.0;
  for (double x : c.s) sum += x * x;
  const double norm = sum > 0.0 ? std::sqrt(static_cast<double>(c.s.size()) / sum) : 0.0;
  std::vector<float> out(c.s.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(c.s[i] * norm);
  return out;
}

}  // namespace pool::audio
