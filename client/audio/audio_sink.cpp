// The silent sink's clock, and the choice between OpenAL and silence.
#include "client/audio/audio_sink.h"

#include <algorithm>
#include <cmath>

#include "client/audio/openal_sink.h"

namespace pool::audio {

SilentSink::SilentSink(int rate, std::size_t block, Clock clock)
    : rate_(rate), block_(std::max<std::size_t>(1, block)), clock_(std::move(clock)) {
  if (!clock_) {
    clock_ = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
          .count();
    };
  }
  start_ = clock_();
}

std::size_t SilentSink::framesWanted() {
  const double elapsed = std::max(0.0, clock_() - start_);
  const auto due = static_cast<std::size_t>(std::floor(elapsed * rate_));
  // A stalled caller does not get the whole stall to mix at once.
  const auto max_behind = static_cast<std::size_t>(rate_ / 4);
  if (due > written_ + max_behind) written_ = due - max_behind;
  const std::size_t wanted = due > written_ ? due - written_ : 0;
  return wanted - wanted % block_;
}

void SilentSink::write(std::span<const float> block) {
  written_ += block.size();
}

std::unique_ptr<AudioSink> openSink(const SinkOptions& options,
                                    const std::function<void(const std::string&)>& log) {
  auto say = [&](const std::string& line) {
    if (log) log(line);
  };
  if (options.mute) {
    say("sound: muted");
    return std::make_unique<SilentSink>(options.rate, options.block);
  }
  auto opened = OpenAlSink::open(options);
  if (!opened) {
    say("sound: " + opened.error() + "; playing silently");
    return std::make_unique<SilentSink>(options.rate, options.block);
  }
  say("sound: " + (*opened)->name());
  return std::move(*opened);
}

}  // namespace pool::audio
