// Renders cues block by block, each started at its exact sample inside its block.
#include "client/audio/offline_render.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace pool::audio {

Rendering renderCues(const std::vector<SoundCue>& cues, const SoundBank& bank, MixerOptions options,
                     double tail) {
  options.rate = bank.rate();
  Mixer mixer(options);
  const double end = (cues.empty() ? 0.0 : std::max(0.0, cues.back().t)) + tail;
  Rendering r;
  r.samples.assign(static_cast<std::size_t>(std::ceil(end * bank.rate())), 0.0f);
  constexpr std::size_t kBlock = 256;
  std::size_t next = 0;
  for (std::size_t pos = 0; pos < r.samples.size(); pos += kBlock) {
    const std::size_t n = std::min(kBlock, r.samples.size() - pos);
    for (; next < cues.size(); ++next) {
      const double at = std::max(0.0, cues[next].t) * bank.rate();
      if (at >= static_cast<double>(pos + n)) break;
      const auto delay = static_cast<std::uint32_t>(
          std::clamp(std::lround(at) - static_cast<long>(pos), 0L, static_cast<long>(n - 1)));
      mixer.start(bank.pick(cues[next]), static_cast<float>(cues[next].amplitude), delay);
    }
    mixer.mix(std::span<float>(r.samples.data() + pos, n));
  }
  r.stats = mixer.stats();
  return r;
}

}  // namespace pool::audio
