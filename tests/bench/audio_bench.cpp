// Benchmark: mixing the busiest second of the break (its first) block by block, against real time
// and against mixing a second of silence through the same limiter and clipper; and the sound
// bank's synthesis at start-up.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <vector>

#include "audio/shots.h"
#include "client/audio/offline_render.h"
#include "client/audio/sound_bank.h"
#include "client/audio/sound_cue.h"
#include "ratio_reporter.h"

namespace {

using namespace pool;

const audio::SoundBank& bank() {
  static const audio::SoundBank b;
  return b;
}

/// The cues of the break's first second.
const std::vector<audio::SoundCue>& breakSecond() {
  static const std::vector<audio::SoundCue> cues = [] {
    auto all = audio::cuesFromEvents(audio::test::breakEvents(), audio::ImpactLaws{});
    std::erase_if(all, [](const audio::SoundCue& c) { return c.t >= 1.0; });
    return all;
  }();
  return cues;
}

/// One second of audio mixed as the board mixes it, each cue started at its sample.
void mixSecond(benchmark::State& state, const std::vector<audio::SoundCue>& cues) {
  const double tail = 1.0 - (cues.empty() ? 0.0 : cues.back().t);
  std::uint64_t started = 0;
  for (auto _ : state) {
    const auto mixed = audio::renderCues(cues, bank(), {}, tail);
    benchmark::DoNotOptimize(mixed.samples.data());
    started = mixed.stats.started;
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
    ->Repetitions(pool::bench::reps(15))
    ->ReportAggregatesOnly(true);

/// Baseline: a second with no sound, through the same limiter and clipper.
void BM_BaselineMixSilentSecond(benchmark::State& state) {
  mixSecond(state, {});
}
BENCHMARK(BM_BaselineMixSilentSecond)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(pool::bench::reps(15))
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
    ->Repetitions(pool::bench::reps(5))
    ->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  pool::bench::RatioReporter reporter("BM_Baseline");
  const int status = pool::bench::runBenchmarks(argc, argv, reporter);
  std::printf(
      "(a ratio under 1 is the cost of the break's voices over the silent mix; "
      "x_realtime: seconds of audio mixed per second of CPU)\n");
  return status;
}
