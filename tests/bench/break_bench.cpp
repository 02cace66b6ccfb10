// Benchmark: the 8-ball break simulated to rest (the shared "break" scene), against fixed-step ODE.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <stdexcept>

#include "physics/ode_world.h"
#include "physics/simulation.h"
#include "ratio_reporter.h"
#include "scenario/scenario.h"

namespace {

using namespace pool;

const scenario::Scenario& breakScene() {
  static const scenario::Scenario s = [] {
    auto loaded = scenario::loadScenario("break");
    if (!loaded) throw std::runtime_error(loaded.error());
    return *loaded;
  }();
  return s;
}

/// The break from strike to rest, as the server and pool-sim run it.
void BM_BreakToRest(benchmark::State& state) {
  const auto& s = breakScene();
  double simulated = 0;
  std::uint64_t steps = 0, events = 0;
  for (auto _ : state) {
    physics::Simulation sim(s.spec, s.geometry);
    (void)sim.setBalls(s.balls);
    auto out = sim.shoot(s.shot, s.options);
    if (!out || !out->t_rest) {
      state.SkipWithError("break did not come to rest");
      return;
    }
    simulated = *out->t_rest;
    steps = out->stats.steps;
    events = out->stats.events;
    benchmark::DoNotOptimize(out->balls.data());
  }
  state.counters["sim_s"] = simulated;
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["events"] = static_cast<double>(events);
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(
      simulated * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BreakToRest)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(25)
    ->ReportAggregatesOnly(true);

/// The same break on Han (2005)'s one-impulse cushion model, the default before Mathavan (2010):
/// the cost of the cushion model against the same run.
void BM_BreakToRestHan2005Cushions(benchmark::State& state) {
  scenario::Scenario s = breakScene();
  s.spec.models.ball_cushion = "han2005";
  for (auto _ : state) {
    physics::Simulation sim(s.spec, s.geometry);
    (void)sim.setBalls(s.balls);
    auto out = sim.shoot(s.shot, s.options);
    benchmark::DoNotOptimize(out->balls.data());
  }
}
BENCHMARK(BM_BreakToRestHan2005Cushions)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(25)
    ->ReportAggregatesOnly(true);

/// The same break with 60 Hz frames recorded, as the server publishes them.
void BM_BreakToRestWithFrames(benchmark::State& state) {
  const auto& s = breakScene();
  for (auto _ : state) {
    physics::Simulation sim(s.spec, s.geometry);
    (void)sim.setBalls(s.balls);
    physics::SimOptions opt = s.options;
    opt.sample_hz = 60.0;
    auto out = sim.shoot(s.shot, opt);
    benchmark::DoNotOptimize(out->trajectory.data());
  }
}
BENCHMARK(BM_BreakToRestWithFrames)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(25)
    ->ReportAggregatesOnly(true);

/// Baseline: sixteen free ODE bodies stepped at a fixed 1 ms for the break's simulated time,
/// with no collision detection at all (the floor of the fixed-step approach).
void BM_BaselineFixedStepOde1ms(benchmark::State& state) {
  const auto& s = breakScene();
  physics::Simulation probe(s.spec, s.geometry);
  (void)probe.setBalls(s.balls);
  const double duration = probe.shoot(s.shot, s.options)->t_rest.value_or(10.0);
  for (auto _ : state) {
    physics::OdeWorld world(s.spec.params.ball_mass, s.spec.params.ball_radius);
    std::vector<physics::Ball> balls = s.balls;
    for (auto& b : balls) {
      b.vel = physics::Vec3(1, 0, 0);
      world.addBall(b);
    }
    for (size_t i = 0; i < balls.size(); ++i) world.setBall(static_cast<int>(i), balls[i], true);
    const std::vector<physics::Vec3> acc(balls.size(), physics::Vec3(-0.1, 0, 0));
    for (double t = 0; t < duration; t += 1e-3) world.step(1e-3, acc, acc, balls);
    benchmark::DoNotOptimize(balls.data());
  }
}
BENCHMARK(BM_BaselineFixedStepOde1ms)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(25)
    ->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  pool::bench::RatioReporter reporter("BM_Baseline");
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
