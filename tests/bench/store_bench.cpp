// Benchmark: what the store adds to an accepted shot. Committing a break's record (state, table,
// events, verdict, the match after it; WAL, synchronous = FULL) against encoding it alone.
#include <benchmark/benchmark.h>
#include <stdlib.h>

#include <cstdio>
#include <string>

#include "game/loaded_table.h"
#include "protocol/command_signature.h"
#include "protocol/key_pair.h"
#include "ratio_reporter.h"
#include "server/match/match.h"
#include "server/store/match_store.h"
#include "server/store/record_json.h"

namespace {

using namespace pool;

/// A seated match on the 9-ft table with its break accepted: the record and the match after it.
struct BreakRecord {
  server::ShotRecord record;
  server::MatchSnapshot after;
};

const BreakRecord& breakRecord() {
  static const BreakRecord made = [] {
    auto kit = game::loadSharedTable("wpa-9ft");
    if (!kit) {
      std::fprintf(stderr, "%s\n", kit.error().c_str());
      std::exit(1);
    }
    server::Match match("srv-1", "Table 1", std::make_shared<server::ShotRunner>(*kit), {}, 42);
    const protocol::KeyPair ada = protocol::generateKeyPair();
    match.takeSeat(0, "Ada", "a", 0x1111, ada.publicKey());
    match.takeSeat(1, "Bob", "b", 0x2222, protocol::generateKeyPair().publicKey());
    protocol::ShotRequest r;
    r.match = "srv-1";
    r.seat_token = 0x1111;
    r.seq = 1;
    r.cue.speed = 8.0;
    r.cue.tip_height = 0.1;
    protocol::signCommand(r, ada);
    const auto answer = match.handleShot(r, 0.0);
    if (!answer.record) {
      std::fprintf(stderr, "the break was refused: %s\n", answer.rejection.text.c_str());
      std::exit(1);
    }
    BreakRecord out{*answer.record, match.snapshot()};
    out.after.number = 1;
    return out;
  }();
  return made;
}

/// A fresh database in a scratch folder, removed afterwards.
struct ScratchStore {
  ScratchStore() {
    std::string pattern = "/tmp/pool-store-bench-XXXXXX";
    folder = ::mkdtemp(pattern.data()) ? pattern : "/tmp";
    auto opened = store::MatchStore::open(folder + "/pool.db");
    if (!opened) {
      std::fprintf(stderr, "%s\n", opened.error().c_str());
      std::exit(1);
    }
    store = std::move(*opened);
  }
  ~ScratchStore() {
    store.reset();
    if (folder != "/tmp") std::system(("rm -rf '" + folder + "'").c_str());
  }
  std::string folder;
  std::unique_ptr<store::MatchStore> store;
};

void BM_BaselineEncodeShot(benchmark::State& state) {
  const BreakRecord& b = breakRecord();
  for (auto _ : state) {
    std::size_t bytes =
        store::commandJson(b.record.command).size() + store::gameJson(b.record.state).size() +
        store::ballsJson(b.record.before).size() + store::intentJson(b.record.intent).size() +
        store::eventsJson(b.record.events).size() + store::ballsJson(b.record.after).size() +
        store::verdictJson(b.record.verdict).size() + store::gameJson(b.after.game).size() +
        store::ballsJson(b.after.balls).size();
    benchmark::DoNotOptimize(bytes);
  }
}
BENCHMARK(BM_BaselineEncodeShot)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(pool::bench::reps(9))
    ->ReportAggregatesOnly(true);

void BM_CommitShot(benchmark::State& state) {
  const BreakRecord& b = breakRecord();
  ScratchStore scratch;
  for (auto _ : state) scratch.store->recordShot(b.record, "legal", b.after);
  state.counters["events"] = static_cast<double>(b.record.events.size());
}
BENCHMARK(BM_CommitShot)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(pool::bench::reps(9))
    ->ReportAggregatesOnly(true);

void BM_CommitMatchChange(benchmark::State& state) {
  const BreakRecord& b = breakRecord();
  ScratchStore scratch;
  for (auto _ : state) scratch.store->saveMatches("srv", 1, {b.after});
}
BENCHMARK(BM_CommitMatchChange)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(pool::bench::reps(9))
    ->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  pool::bench::RatioReporter reporter("BM_Baseline", /*wall_clock=*/true);
  return pool::bench::runBenchmarks(argc, argv, reporter);
}
