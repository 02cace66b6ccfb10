// Benchmark: the 8-ball break simulated to rest (the shared "break" scene) and 100 breaks varied by
// seed, against fixed-step ODE, with the time split by part of the engine.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "core/split_mix64.h"
#include "physics/ode_world.h"
#include "physics/simulation.h"
#include "ratio_reporter.h"
#include "scenario/scenario.h"
#include "table/rack.h"

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

/// The standard break with the cue ball's spot, the aim and the speed drawn from `seed`: the cue
/// ball anywhere in a 0.2 m × 0.8 m box behind the head spot, aimed at the apex ball's centre
/// offset sideways by up to ±0.5 R (a fuller or thinner hit on it), cue speed 6 to 10 m/s. The
/// rack is the same (labels do not matter to a label-blind solver; the geometry does).
scenario::Scenario variedBreak(std::uint64_t seed) {
  scenario::Scenario s = breakScene();
  SplitMix64 rng(seed);
  const table::Spots spots = table::spotsFor(s.spec);
  const double R = s.spec.params.ball_radius;
  physics::Ball& cue = s.balls.front();  // sorted by id: the cue ball first
  cue.pos.x() = spots.head_spot.x() - 0.2 * rng.uniform();
  cue.pos.y() = spots.head_spot.y() + 0.8 * (rng.uniform() - 0.5);
  const double offset = R * (rng.uniform() - 0.5);  // ±0.5 R
  const Eigen::Vector2d to_apex = spots.foot_spot - cue.pos.head<2>();
  const Eigen::Vector2d side(-to_apex.y(), to_apex.x());
  const Eigen::Vector2d aim = to_apex + offset * side.normalized();
  s.shot.yaw = std::atan2(aim.y(), aim.x());
  s.shot.speed = 6.0 + 4.0 * rng.uniform();
  return s;
}

constexpr int kVaried = 100;

const std::vector<scenario::Scenario>& variedBreaks() {
  static const std::vector<scenario::Scenario> all = [] {
    std::vector<scenario::Scenario> v;
    for (int k = 0; k < kVaried; ++k) v.push_back(variedBreak(static_cast<std::uint64_t>(k)));
    return v;
  }();
  return all;
}

/// One shot from placement to rest, as the server and pool-sim run it.
Result<physics::ShotOutcome> runShot(const scenario::Scenario& s, bool profile = false) {
  physics::Simulation sim(s.spec, s.geometry);
  if (auto placed = sim.setBalls(s.balls); !placed) {
    return Result<physics::ShotOutcome>::fail(placed.error());
  }
  physics::SimOptions options = s.options;
  options.profile = profile;
  return sim.shoot(s.shot, options);
}

/// The break from strike to rest, as the server and pool-sim run it.
void BM_BreakToRest(benchmark::State& state) {
  const auto& s = breakScene();
  double simulated = 0;
  std::uint64_t steps = 0, events = 0;
  for (auto _ : state) {
    auto out = runShot(s);
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
    ->Repetitions(pool::bench::reps(25))
    ->ReportAggregatesOnly(true);

/// The 100 varied breaks, one after another (time per iteration: all 100).
void BM_HundredVariedBreaks(benchmark::State& state) {
  const auto& all = variedBreaks();
  for (auto _ : state) {
    for (const auto& s : all) {
      auto out = runShot(s);
      benchmark::DoNotOptimize(out->balls.data());
    }
  }
}
BENCHMARK(BM_HundredVariedBreaks)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(pool::bench::reps(5))
    ->ReportAggregatesOnly(true);

/// The same break on Han (2005)'s one-impulse cushion model, the default before Mathavan (2010):
/// the cost of the cushion model against the same run.
void BM_BreakToRestHan2005Cushions(benchmark::State& state) {
  scenario::Scenario s = breakScene();
  s.spec.models.ball_cushion = "han2005";
  for (auto _ : state) {
    auto out = runShot(s);
    benchmark::DoNotOptimize(out->balls.data());
  }
}
BENCHMARK(BM_BreakToRestHan2005Cushions)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(pool::bench::reps(25))
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
    ->Repetitions(pool::bench::reps(25))
    ->ReportAggregatesOnly(true);

/// Baseline: sixteen free ODE bodies stepped at a fixed 1 ms for the break's simulated time,
/// with no collision detection at all (the floor of the fixed-step approach).
void BM_BaselineFixedStepOde1ms(benchmark::State& state) {
  const auto& s = breakScene();
  const double duration = runShot(s)->t_rest.value_or(10.0);
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
    ->Repetitions(pool::bench::reps(25))
    ->ReportAggregatesOnly(true);

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Each varied break's CPU time (the median of `rounds` runs), then their mean and 90th
/// percentile over the 100; and the time split by part, from one profiled run of each. Returns
/// false if a break did not come to rest or the figures are out of a generous bound.
bool reportVariedBreaks(double baseline_ms, int rounds) {
  const auto& all = variedBreaks();
  std::vector<std::vector<double>> times(all.size());
  double simulated = 0.0;
  for (int r = 0; r < rounds; ++r) {
    for (size_t k = 0; k < all.size(); ++k) {
      const double t0 = threadCpuSeconds();
      auto out = runShot(all[k]);
      times[k].push_back(1e3 * (threadCpuSeconds() - t0));
      if (!out || !out->t_rest) {
        std::printf("varied break %zu did not come to rest: %s\n", k,
                    out ? "truncated" : out.error().c_str());
        return false;
      }
      if (r == 0) simulated += *out->t_rest;
    }
  }
  std::vector<double> per_break;
  for (auto& t : times) {
    std::sort(t.begin(), t.end());
    per_break.push_back(t[t.size() / 2]);
  }
  double mean = 0.0;
  for (double t : per_break) mean += t;
  mean /= static_cast<double>(per_break.size());
  std::sort(per_break.begin(), per_break.end());
  const double p90 = per_break[static_cast<size_t>(0.9 * static_cast<double>(per_break.size()))];
  const double std_t = runShot(breakScene())->t_rest.value_or(1.0);
  const double mean_sim = simulated / static_cast<double>(all.size());
  // The fixed-step baseline costs in proportion to the simulated time.
  const double base = baseline_ms * mean_sim / std_t;
  std::printf(
      "\n%d breaks, cue-ball spot, aim offset and speed varied by seed (CPU per break, "
      "median of %d runs):\n",
      kVaried, rounds);
  std::printf(
      "  mean %.3f ms   p90 %.3f ms   min %.3f ms   max %.3f ms   (%.2f s simulated "
      "on average)\n",
      mean, p90, per_break.front(), per_break.back(), mean_sim);
  if (base > 0) {
    std::printf("  fixed-step ODE baseline for the same simulated time: %.3f ms   x%.1f\n", base,
                base / mean);
  }

  // The split by part, from profiled runs: each part's median over the runs (a run preempted on a
  // loaded machine, its wall-clock time charged to whichever part was running, is an outlier the
  // median leaves out), as a share of the medians' sum, applied to the unprofiled CPU time.
  auto printSplit = [](const char* what, const std::vector<physics::PartTimes>& runs, double cpu_ms,
                       int profiled) {
    physics::PartTimes median{};
    double total = 0.0;
    for (size_t p = 0; p < physics::kPartCount; ++p) {
      std::vector<double> t;
      for (const auto& r : runs) t.push_back(r[p]);
      std::sort(t.begin(), t.end());
      median[p] = t[t.size() / 2];
      total += median[p];
    }
    std::printf("\ntime by part, %s (median shares of %d profiled runs, of %.3f ms CPU):\n", what,
                profiled, cpu_ms);
    for (size_t p = 0; p < physics::kPartCount; ++p) {
      const double share = total > 0 ? median[p] / total : 0.0;
      std::printf("  %-14s %5.1f %%  %8.4f ms\n", physics::partName(static_cast<physics::Part>(p)),
                  100.0 * share, share * cpu_ms);
    }
  };
  std::vector<physics::PartTimes> standard;
  const int standard_runs = 20 * rounds;
  std::vector<double> standard_times;
  for (int r = 0; r < standard_runs; ++r) {
    const double t0 = threadCpuSeconds();
    benchmark::DoNotOptimize(runShot(breakScene()));
    standard_times.push_back(1e3 * (threadCpuSeconds() - t0));
    standard.push_back(runShot(breakScene(), true)->stats.seconds);
  }
  std::sort(standard_times.begin(), standard_times.end());
  const double standard_ms = standard_times[standard_times.size() / 2];
  std::printf("\nthe standard break: %.3f ms CPU (median of %d runs)\n", standard_ms,
              standard_runs);
  printSplit("the standard break", standard, standard_ms, standard_runs);
  // The varied breaks differ from each other: each part's median over the rounds of each break,
  // summed over the breaks.
  physics::PartTimes varied_sum{};
  for (const auto& s : all) {
    std::vector<physics::PartTimes> of_break;
    for (int r = 0; r < rounds; ++r) of_break.push_back(runShot(s, true)->stats.seconds);
    for (size_t p = 0; p < physics::kPartCount; ++p) {
      std::vector<double> t;
      for (const auto& b : of_break) t.push_back(b[p]);
      std::sort(t.begin(), t.end());
      varied_sum[p] += t[t.size() / 2];
    }
  }
  printSplit("the 100 varied breaks", {varied_sum}, mean, rounds * kVaried);

  // A generous bound (sanitizers, a loaded machine): a break costs well under 50 ms.
  constexpr double kBoundMs = 50.0;
  if (!(mean < kBoundMs)) {
    std::printf("mean break %.3f ms is over the %.0f ms bound\n", mean, kBoundMs);
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  pool::bench::RatioReporter reporter("BM_Baseline");
  const int status = pool::bench::runBenchmarks(argc, argv, reporter);
  const bool ok =
      reportVariedBreaks(reporter.median("BM_BaselineFixedStepOde1ms"), pool::bench::smokeOr(3, 1));
  return status != 0 ? status : ok ? 0 : 1;
}
