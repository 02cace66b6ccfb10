// What the server's signature costs per published sample: a 16-ball TableSnapshot converted to
// its wire sample (the baseline), then sealed by the server, then checked by a client (the
// canonical encoding, the Ed25519 signature or verification), beside the baseline of the same run.
#include <benchmark/benchmark.h>

#include "net/message_convert.h"
#include "net/server_seal.h"
#include "protocol/server_signature.h"
#include "ratio_reporter.h"

namespace {

using namespace pool;

protocol::TableFrame sixteenBalls() {
  protocol::TableFrame frame;
  frame.match = "srv-1";
  frame.shot_number = 3;
  frame.frame = 40;
  frame.sim_time = 40.0 / 60.0;
  for (int id = 0; id < 16; ++id) {
    physics::Ball b;
    b.id = id;
    b.pos = physics::Vec3(0.05 * id - 0.4, 0.02 * id - 0.15, 0.028575);
    b.vel = physics::Vec3(0.3, -0.1, 0.0);
    frame.balls.push_back(b);
  }
  return frame;
}

void BM_BaselineToWire(benchmark::State& state) {
  const auto frame = sixteenBalls();
  for (auto _ : state) {
    auto sample = net::toWire(frame);
    benchmark::DoNotOptimize(sample->balls._length);
  }
}
BENCHMARK(BM_BaselineToWire)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(pool::bench::reps(7))
    ->ReportAggregatesOnly(true);

void BM_SealedBody(benchmark::State& state) {
  const auto frame = sixteenBalls();
  auto sample = net::toWire(frame);
  std::size_t bytes = 0;
  for (auto _ : state) {
    bytes = net::sealedBody(*sample).size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_SealedBody)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(pool::bench::reps(7))
    ->ReportAggregatesOnly(true);

void BM_ToWireAndSeal(benchmark::State& state) {
  const auto frame = sixteenBalls();
  const auto key = protocol::generateKeyPair();
  for (auto _ : state) {
    auto sample = net::toWire(frame);
    net::seal(*sample, key);
    benchmark::DoNotOptimize(sample->signature._length);
  }
}
BENCHMARK(BM_ToWireAndSeal)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(pool::bench::reps(7))
    ->ReportAggregatesOnly(true);

void BM_CheckReceived(benchmark::State& state) {
  const auto frame = sixteenBalls();
  const auto key = protocol::generateKeyPair();
  auto sample = net::toWire(frame);
  net::seal(*sample, key);
  for (auto _ : state) {
    const auto seal = protocol::checkSeal(net::sealedOf(*sample));
    if (!seal) state.SkipWithError(seal.error().c_str());
  }
}
BENCHMARK(BM_CheckReceived)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(pool::bench::reps(7))
    ->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  pool::bench::RatioReporter reporter("BM_Baseline");
  return pool::bench::runBenchmarks(argc, argv, reporter);
}
