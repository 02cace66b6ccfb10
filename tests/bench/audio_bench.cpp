// Benchmark: mixing the busiest second of the break (its first) block by block, against real time
// and against mixing a second of silence through the same limiter and clipper; and the sound
// bank's synthesis at start-up.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "client/audio/mixer.h"
#include "client/audio/sound_bank.h"
#include "client/audio/sound_cue.h"
#include "ratio_reporter.h"
#include "scenario/scenario.h"

namespace {

using namespace pool;

constexpr std::size_t kBlock = 512;  // the board's block: ≈ 11 ms at 48 kHz

const audio::SoundBank& bank() {
  static const audio::SoundBank b;
  return b;
}

/// The cues of the break's first second.
const std::vector<audio::SoundCue>& breakSecond() {
  static const std::vector<audio::SoundCue> cues = [] {
    auto scene = scenario::loadScenario("break");
    if (!scene) throw std::runtime_error(scene.error());
    auto outcome = scenario::runScenario(*scene);
    if (!outcome) throw std::runtime_error(outcome.error());
    auto all = audio::cuesFromEvents(outcome->events, audio::ImpactLaws{});
    std::erase_if(all, [](const audio::SoundCue& c) { return c.t >= 1.0; });
    return all;
  }();
  return cues;
}

/// One second of audio mixed as the board does it: cues started in the block they fall in.
void mixSecond(benchmark::State& state, const std::vector<audio::SoundCue>& cues) {
  const int rate = bank().rate();
  std::vector<float> block(kBlock);
  std::uint64_t started = 0;
  for (auto _ : state) {
    audio::Mixer mixer;
    std::size_t next = 0;
    for (std::size_t pos = 0; pos < static_cast<std::size_t>(rate); pos += kBlock) {
      for (; next < cues.size() && cues[next].t * rate < static_cast<double>(pos + kBlock);
           ++next) {
        mixer.start(bank().pick(cues[next]), static_cast<float>(cues[next].amplitude));
      }
      mixer.mix(block);
      benchmark::DoNotOptimize(block.data());
    }
    started = mixer.stats().started;
  }
  state.counters["sounds"] = static_cast<double>(started);
  // Seconds of audio per second of CPU: how many times faster than real time.
  state.counters["x_realtime"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_MixBreakFirstSecond(benchmark::State& state) {
  mixSecond(state, breakSecond());
}
BENCHMARK(BM_MixBreakFirstSecond)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(15)
    ->ReportAggregatesOnly(true);

/// Baseline: a second with no sound, through the same limiter and clipper.
void BM_BaselineMixSilentSecond(benchmark::State& state) {
  mixSecond(state, {});
}
BENCHMARK(BM_BaselineMixSilentSecond)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(15)
    ->ReportAggregatesOnly(true);

/// What a SoundBoard spends at construction: synthesising every template sound.
void BM_SynthesiseBank(benchmark::State& state) {
  for (auto _ : state) {
    audio::SoundBank b;
    benchmark::DoNotOptimize(&b);
  }
}
BENCHMARK(BM_SynthesiseBank)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  pool::bench::RatioReporter reporter("BM_Baseline");
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf(
      "(a ratio under 1 is the cost of the break's voices over the silent mix; "
      "x_realtime: seconds of audio mixed per second of CPU)\n");
  benchmark::Shutdown();
  return 0;
}
