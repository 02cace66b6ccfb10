// Voices summed, then a peak limiter and a soft clipper, block by block without allocating.
#include "client/audio/mixer.h"

#include <algorithm>
#include <cmath>

namespace pool::audio {

float softClip(float x, float knee) {
  const float a = std::fabs(x);
  if (a <= knee) return x;
  const float bent = knee + (1.0f - knee) * std::tanh((a - knee) / (1.0f - knee));
  return std::copysign(std::min(bent, 0.9999f), x);
}

float Mixer::Voice::remaining() const {
  return length == 0 ? 0.0f : gain * static_cast<float>(length - pos) / static_cast<float>(length);
}

Mixer::Mixer(const MixerOptions& options)
    : options_(options),
      voices_(static_cast<std::size_t>(std::max(1, options.voices))),
      release_coef_(static_cast<float>(
          std::exp(-1.0 / (std::max(1e-4, options.release) * std::max(1, options.rate))))) {}

void Mixer::start(std::span<const float> sound, float gain, std::uint32_t delay) {
  if (sound.empty() || !(gain > 0.0f)) return;
  // A free voice, else the one with the least loudness left.
  Voice* target = nullptr;
  for (Voice& v : voices_) {
    if (!v.busy()) {
      target = &v;
      break;
    }
    if (!target || v.remaining() < target->remaining()) target = &v;
  }
  if (target->busy()) {
    if (target->remaining() >= gain) {
      ++stats_.dropped;
      return;
    }
    ++stats_.stolen;
  }
  *target = {sound.data(), static_cast<std::uint32_t>(sound.size()), 0, delay, gain};
  ++stats_.started;
  stats_.max_active = std::max(stats_.max_active, active());
}

void Mixer::mix(std::span<float> out) {
  std::fill(out.begin(), out.end(), 0.0f);
  const auto frames = static_cast<std::uint32_t>(out.size());
  for (Voice& v : voices_) {
    if (!v.busy()) continue;
    const std::uint32_t skip = std::min(v.delay, frames);
    v.delay -= skip;
    const std::uint32_t n = std::min(frames - skip, v.length - v.pos);
    const float* src = v.data + v.pos;
    float* dst = out.data() + skip;
    for (std::uint32_t i = 0; i < n; ++i) dst[i] += v.gain * src[i];
    v.pos += n;
    if (v.pos >= v.length) v = Voice{};
  }
  // The limiter follows peaks instantly and lets go slowly: the gained sum never exceeds
  // `limit`, and the soft clipper only rounds what is left near full scale.
  for (float& s : out) {
    const float x = s * options_.master;
    const float a = std::fabs(x);
    stats_.peak_in = std::max(stats_.peak_in, a);
    envelope_ = std::max(a, envelope_ * release_coef_);
    float y = x;
    if (envelope_ > options_.limit) {
      y *= options_.limit / envelope_;
      ++stats_.limited;
    }
    s = softClip(y, options_.knee);
    stats_.peak_out = std::max(stats_.peak_out, std::fabs(s));
  }
}

void Mixer::stopAll() {
  for (Voice& v : voices_) v = Voice{};
}

int Mixer::active() const {
  return static_cast<int>(
      std::count_if(voices_.begin(), voices_.end(), [](const Voice& v) { return v.busy(); }));
}

}  // namespace pool::audio
