// Benchmark: the bot under execution noise, in 8-, 9- and 10-ball: its break on seeded hand racks
// (pots, legal, keeps the turn) against a centred 9 m/s break and the grid the breaks come from;
// whole racks alone at the table, exact against sampled planning and at each level; and each
// level against the one below it. Three-cushion: points per inning from seeded positions.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_run.h"
#include "client/bot/ai/bot_level.h"
#include "client/bot/ai/break_shot.h"
#include "client/bot/ai/carom_search.h"
#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/shot_planner.h"
#include "client/bot/ai/shot_verifier.h"
#include "rules/game_state.h"
#include "rules/three_cushion.h"
#include "table/rack.h"

namespace {

using namespace pool;
using bot::Vec2;

const bot::TableView& tableFor(rules::Game game) {
  static std::vector<std::unique_ptr<bot::TableView>> views(3);
  auto& view = views[static_cast<std::size_t>(game)];
  if (!view) {
    auto loaded = bot::loadTableView("wpa-9ft");
    if (!loaded) throw std::runtime_error(loaded.error());
    view = std::make_unique<bot::TableView>(std::move(*loaded));
    view->rules.game = game;
  }
  return *view;
}

/// The hand rack of `seed` for `game`, the cue ball on the head spot (the break places it).
std::vector<physics::Ball> rackOf(const bot::TableView& view, std::uint64_t seed) {
  const table::RackType type = rules::rackTypeOf(view.rules.game);
  std::vector<physics::Ball> balls(16);
  for (int id = 0; id < 16; ++id) {
    auto& b = balls[static_cast<std::size_t>(id)];
    b.id = id;
    b.state = physics::MotionState::Pocketed;
    b.pos = physics::Vec3(0, 0, -0.2);
  }
  const double r = view.radius();
  const auto placed = table::rackFor(type, view.spec, r, seed, table::RackGenerator::Hand);
  for (const auto& p : placed)
    balls[static_cast<std::size_t>(p.id)] = physics::restingBall(p.id, p.pos, r);
  balls[0] = physics::restingBall(0, view.context.spots.head_spot, r);
  return balls;
}

struct Tally {
  int breaks = 0, pots = 0, legal = 0, keeps = 0;
  void add(const bot::Trial& t) {
    ++breaks;
    pots += t.verdict.pocketed.empty() ? 0 : 1;
    legal += t.verdict.legal() ? 1 : 0;
    keeps += t.verdict.turn_continues ? 1 : 0;
  }
  double share(int n) const { return breaks ? 100.0 * n / breaks : 0.0; }
};

/// `shot` played with the olympiad noise on `balls` (the cue ball where the shot puts it).
bot::Trial played(bot::ShotVerifier& verifier, std::vector<physics::Ball> balls,
                  const bot::PlannedShot& shot, bot::Rng& rng, const bot::TableView& view) {
  if (shot.cue_ball_at) balls[0] = physics::restingBall(0, *shot.cue_ball_at, view.radius());
  bot::PlannedShot noisy = shot;
  noisy.cue = bot::perturbed(shot.cue, bot::olympiadNoise(view.radius()), rng);
  return verifier.run(balls, rules::newRack(0), noisy);
}

void report(benchmark::State& state, const Tally& t) {
  state.counters["pots%"] = t.share(t.pots);
  state.counters["legal%"] = t.share(t.legal);
  state.counters["keeps%"] = t.share(t.keeps);
}

constexpr std::uint64_t kFirstRack = 5000;  // not the grid's racks: the figures are out of sample

int racks() {
  return pool::bench::smokeOr(200, 3);
}

void BM_BotBreak(benchmark::State& state) {
  const auto game = static_cast<rules::Game>(state.range(0));
  const bot::TableView& view = tableFor(game);
  bot::ShotVerifier verifier(view);
  Tally tally;
  double plan_ms = 0.0;
  for (auto _ : state) {
    bot::Rng rng(11);
    tally = {};
    plan_ms = 0.0;
    for (int k = 0; k < racks(); ++k) {
      const auto balls = rackOf(view, kFirstRack + static_cast<std::uint64_t>(k));
      bot::ShotPlanner planner(view);
      const auto start = std::chrono::steady_clock::now();
      const bot::PlannedShot shot = planner.plan(balls, rules::newRack(0));
      plan_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count();
      tally.add(played(verifier, balls, shot, rng, view));
    }
  }
  report(state, tally);
  state.counters["plan_ms"] = plan_ms / racks();
}
BENCHMARK(BM_BotBreak)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_BaselineCentredBreak(benchmark::State& state) {
  const auto game = static_cast<rules::Game>(state.range(0));
  const bot::TableView& view = tableFor(game);
  bot::ShotVerifier verifier(view);
  Tally tally;
  for (auto _ : state) {
    bot::Rng rng(11);
    tally = {};
    for (int k = 0; k < racks(); ++k) {
      const auto balls = rackOf(view, kFirstRack + static_cast<std::uint64_t>(k));
      const Vec2 apex = bot::apexBall(view, balls);
      const auto shot = bot::breakShot(view, apex, {0.0, 0.0, 9.0, -0.1}, 1);
      tally.add(played(verifier, balls, shot, rng, view));
    }
  }
  report(state, tally);
}
BENCHMARK(BM_BaselineCentredBreak)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);

/// One axis of the break grid: every value, or its two ends in the smoke run (16 strokes of the
/// grid's 864: the sweep's path, not its figures).
std::vector<double> gridAxis(std::initializer_list<double> values) {
  if (!pool::bench::smoke()) return values;
  return {*values.begin(), *(values.end() - 1)};
}

/// The grid measuredBreaks was chosen from: each stroke over 200 racks (seeds 1000–1199).
void BM_BreakGrid(benchmark::State& state) {
  const auto game = static_cast<rules::Game>(state.range(0));
  const bot::TableView& view = tableFor(game);
  bot::ShotVerifier verifier(view);
  const int n = pool::bench::smokeOr(200, 1);
  struct Row {
    bot::BreakStroke stroke;
    Tally tally;
  };
  std::vector<Row> rows;
  for (auto _ : state) {
    rows.clear();
    bot::Rng rng(7);
    for (double y : gridAxis({0.0, 0.1, 0.2, 0.3, 0.4, 0.55})) {
      for (double offset : gridAxis({-0.6, -0.45, -0.3, -0.15, 0.0, 0.15, 0.3, 0.45, 0.6})) {
        for (double speed : gridAxis({9.0, 10.0, 11.0, 12.0})) {
          for (double tip : gridAxis({-0.3, -0.1, 0.2, 0.4})) {
            Row row{{y, offset, speed, tip}, {}};
            for (int k = 0; k < n; ++k) {
              const auto balls = rackOf(view, 1000 + static_cast<std::uint64_t>(k));
              const auto shot = bot::breakShot(view, bot::apexBall(view, balls), row.stroke, 1);
              row.tally.add(played(verifier, balls, shot, rng, view));
            }
            rows.push_back(row);
          }
        }
      }
    }
  }
  std::sort(rows.begin(), rows.end(),
            [](const Row& a, const Row& b) { return a.tally.keeps > b.tally.keeps; });
  std::printf("%s-ball break grid over %d racks, best first (pots / legal / keeps the turn):\n",
              game == rules::Game::EightBall  ? "8"
              : game == rules::Game::NineBall ? "9"
                                              : "10",
              n);
  for (std::size_t i = 0; i < std::min<std::size_t>(rows.size(), 8); ++i) {
    const Row& r = rows[i];
    std::printf("  y %.2f offset %+.2f R speed %4.1f tip %+.1f: %5.1f / %5.1f / %5.1f %%\n",
                r.stroke.y, r.stroke.offset, r.stroke.speed, r.stroke.tip,
                r.tally.share(r.tally.pots), r.tally.share(r.tally.legal),
                r.tally.share(r.tally.keeps));
  }
}
BENCHMARK(BM_BreakGrid)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);

/// What the bot does with a whole rack, alone at the table (it plays both seats), every shot
/// under the olympiad noise: pots, fouls, innings and break-and-runs.
struct RunTally {
  int racks = 0, break_and_runs = 0, won = 0;
  int pot_tries = 0, pots = 0;  ///< called pots (the break and safeties excluded)
  int shots = 0, fouls = 0, innings = 0, inning_balls = 0;
  int safeties = 0, fallbacks = 0;
  std::vector<double> plan_ms;
};

/// Plays rack `seed` of `view`'s game from `breaker`'s break to its end (or 80 shots; 3 in the
/// smoke run), each seat planning with its options and playing under their noise. The winner's
/// seat, or -1 (a re-rack, or no end within the shots allowed).
int runRack(const bot::TableView& view, const std::array<const bot::PlannerOptions*, 2>& seats,
            int breaker, std::uint64_t seed, bot::ShotVerifier& verifier, bot::Rng& rng,
            RunTally& tally) {
  auto balls = rackOf(view, seed);
  rules::GameState state = rules::newRack(breaker);
  bool turn_changed = false;
  ++tally.racks;
  // The smoke run plays the first shots of a rack only: the planner's path, not its figures.
  const int max_shots = pool::bench::smokeOr(80, 3);
  for (int shot_no = 0; shot_no < max_shots; ++shot_no) {
    const bot::PlannerOptions& options = *seats[static_cast<std::size_t>(state.shooter)];
    bot::ShotPlanner planner(view, options);
    const auto start = std::chrono::steady_clock::now();
    const bot::PlannedShot shot = planner.plan(balls, state);
    tally.plan_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    if (!bot::shoots(shot)) return -1;  // a re-rack: the rack ends here
    bot::PlannedShot noisy = shot;
    noisy.cue = bot::perturbed(shot.cue, options.noise, rng);
    const bot::Trial trial = verifier.run(balls, state, noisy);
    if (!trial.judged) return -1;
    const bool breaking = shot.kind == bot::ShotKind::Break;
    ++tally.shots;
    if (!trial.verdict.legal()) ++tally.fouls;
    if (shot.kind == bot::ShotKind::Safety) ++tally.safeties;
    if (shot.kind == bot::ShotKind::Fallback) ++tally.fallbacks;
    if (shot.kind == bot::ShotKind::Pot) {
      ++tally.pot_tries;
      if (trial.potted_call && trial.verdict.legal()) ++tally.pots;
    }
    if (!breaking && trial.verdict.legal()) {
      tally.inning_balls += static_cast<int>(trial.verdict.pocketed.size());
    }
    const bool inning_ends = !trial.verdict.turn_continues || trial.verdict.game_over;
    if (!breaking && inning_ends) ++tally.innings;
    if (trial.verdict.game_over) {
      if (trial.verdict.winner == breaker) ++tally.won;
      if (trial.verdict.winner == breaker && !turn_changed) ++tally.break_and_runs;
      return trial.verdict.winner;
    }
    if (trial.verdict.rerack) return -1;
    if (!trial.verdict.turn_continues) turn_changed = true;
    balls = trial.after;
    state = trial.verdict.next;
  }
  return -1;
}

double percentileOf(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

const char* gameName(rules::Game game) {
  return game == rules::Game::EightBall ? "8" : game == rules::Game::NineBall ? "9" : "10";
}

/// The bot alone at the table for `n` racks from kFirstRack, planning with `options` and playing
/// under `options.noise`; the figures go to `state` and one printed line headed `label`.
void benchRacks(benchmark::State& state, rules::Game game, const bot::PlannerOptions& options,
                const std::string& label) {
  const bot::TableView& view = tableFor(game);
  bot::ShotVerifier verifier(view);
  RunTally t;
  const int n = pool::bench::smokeOr(100, 1);
  for (auto _ : state) {
    bot::Rng rng(23);
    t = {};
    for (int k = 0; k < n; ++k) {
      runRack(view, {&options, &options}, 0, kFirstRack + static_cast<std::uint64_t>(k), verifier,
              rng, t);
    }
  }
  const auto share = [](int a, int b) { return b ? 100.0 * a / b : 0.0; };
  const double per_inning = t.innings ? 1.0 * t.inning_balls / t.innings : 0.0;
  state.counters["pots%"] = share(t.pots, t.pot_tries);
  state.counters["break_and_run%"] = share(t.break_and_runs, t.racks);
  state.counters["balls_an_inning"] = per_inning;
  state.counters["fouls_per_100"] = share(t.fouls, t.shots);
  state.counters["plan_ms_p50"] = percentileOf(t.plan_ms, 0.5);
  state.counters["plan_ms_p90"] = percentileOf(t.plan_ms, 0.9);
  std::printf(
      "%s-ball, %s, %d racks: pots %.1f %% of %d called, break and run %.1f %%, %.2f balls an "
      "inning, %.1f fouls / 100 shots, %d safeties, %d fallbacks; planning p50 %.0f ms p90 %.0f "
      "ms\n",
      gameName(game), label.c_str(), t.racks, share(t.pots, t.pot_tries), t.pot_tries,
      share(t.break_and_runs, t.racks), per_inning, share(t.fouls, t.shots), t.safeties,
      t.fallbacks, percentileOf(t.plan_ms, 0.5), percentileOf(t.plan_ms, 0.9));
}

/// The games whole racks are played in: 8-, 9- and 10-ball; 8-ball alone in the smoke run (under
/// the sanitizers a rack's planning is slow, and the other games' paths are the break's and the
/// rules' tests').
std::vector<std::int64_t> games() {
  return pool::bench::smoke() ? std::vector<std::int64_t>{0} : std::vector<std::int64_t>{0, 1, 2};
}

/// Under the olympiad noise: pots judged by one exact trial each (no sampling) against
/// the same planner sampling each shortlisted pot 16 times under that noise.
void BM_BotRacks(benchmark::State& state) {
  const auto game = static_cast<rules::Game>(state.range(0));
  bot::PlannerOptions options;
  options.samples = static_cast<int>(state.range(1));
  options.noise = bot::olympiadNoise(tableFor(game).radius());
  benchRacks(state, game, options,
             "olympiad noise, " + std::to_string(options.samples) + " samples a pot");
}
BENCHMARK(BM_BotRacks)
    ->ArgsProduct({games(), {0, 16}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

/// Each level of pool-bot --level, alone at the table.
void BM_BotLevels(benchmark::State& state) {
  const auto game = static_cast<rules::Game>(state.range(0));
  const auto level = static_cast<bot::Level>(state.range(1));
  benchRacks(state, game, bot::plannerOptionsFor(level, tableFor(game).radius()),
             std::string("level ") + bot::toString(level));
}
BENCHMARK(BM_BotLevels)
    ->ArgsProduct({games(), {0, 1, 2, 3}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

/// Each level against the level below it, breaking in turn, over the same racks: the share of
/// racks the stronger level wins (goal: at least 70 %).
void BM_BotHeadToHead(benchmark::State& state) {
  const auto game = static_cast<rules::Game>(state.range(0));
  const auto upper = static_cast<bot::Level>(state.range(1));
  const auto lower = static_cast<bot::Level>(state.range(1) - 1);
  const bot::TableView& view = tableFor(game);
  const bot::PlannerOptions strong = bot::plannerOptionsFor(upper, view.radius());
  const bot::PlannerOptions weak = bot::plannerOptionsFor(lower, view.radius());
  bot::ShotVerifier verifier(view);
  const int n = pool::bench::smokeOr(200, 1);
  int upper_wins = 0, decided = 0;
  for (auto _ : state) {
    bot::Rng rng(29);
    upper_wins = decided = 0;
    for (int k = 0; k < n; ++k) {
      RunTally ignored;
      // The stronger level sits in seat 0; the break alternates.
      const int winner =
          runRack(view, {&strong, &weak}, k % 2, kFirstRack + static_cast<std::uint64_t>(k),
                  verifier, rng, ignored);
      if (winner < 0) continue;
      ++decided;
      upper_wins += winner == 0 ? 1 : 0;
    }
  }
  const double share = decided ? 100.0 * upper_wins / decided : 0.0;
  state.counters["upper_wins%"] = share;
  std::printf("%s-ball, %s against %s: %d of %d racks decided won by %s (%.0f %%, goal >= 70 %%)\n",
              gameName(game), bot::toString(upper), bot::toString(lower), upper_wins, decided,
              bot::toString(upper), share);
}
BENCHMARK(BM_BotHeadToHead)
    ->ArgsProduct({games(), {1, 2, 3}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

/// Three balls at seeded places on the carom table, at least two ball widths apart and clear of
/// the cushions.
std::vector<physics::Ball> caromLayout(const bot::TableView& view, bot::Rng& rng) {
  const double r = view.radius();
  std::vector<physics::Ball> balls;
  while (balls.size() < 3) {
    const Vec2 p((rng.uniform() - 0.5) * (view.spec.length - 6 * r),
                 (rng.uniform() - 0.5) * (view.spec.width - 6 * r));
    const bool clear = std::all_of(balls.begin(), balls.end(), [&](const physics::Ball& b) {
      return (b.pos.head<2>() - p).norm() > 4 * r;
    });
    if (clear) balls.push_back(physics::restingBall(static_cast<int>(balls.size()), p, r));
  }
  return balls;
}

/// Three-cushion innings from seeded positions, the bot alone at the table under the olympiad
/// noise: planned from one exact trial a stroke (0 samples) against the same search replaying its
/// scoring strokes 8 times under that noise. Points per inning is the game's average (UMB; 1.5 and
/// more is a world-class player's, about 0.5 an amateur's).
void BM_CaromInnings(benchmark::State& state) {
  static const bot::TableView view = [] {
    auto loaded = bot::loadTableView("carom-match");
    if (!loaded) throw std::runtime_error(loaded.error());
    bot::TableView v = std::move(*loaded);
    v.rules.game = rules::Game::ThreeCushion;
    v.rules.three_cushion.points_to = 1000;  // innings, not games, are measured
    return v;
  }();
  const int samples = static_cast<int>(state.range(0));
  const int budget = static_cast<int>(state.range(1));
  const bot::ExecutionNoise noise = bot::olympiadNoise(view.radius());
  const int innings = pool::bench::smokeOr(40, 1);
  int points = 0, strokes = 0;
  std::vector<double> plan_ms;
  for (auto _ : state) {
    bot::Rng rng(41);
    bot::ShotVerifier verifier(view);
    points = strokes = 0;
    for (int k = 0; k < innings; ++k) {
      auto balls = caromLayout(view, rng);
      rules::GameState game = rules::newRackOf(rules::Game::ThreeCushion, 0);
      game.phase = rules::Phase::Open;
      for (int shot = 0; shot < 30; ++shot) {  // a run of 30 ends the inning all the same
        const auto start = std::chrono::steady_clock::now();
        const bot::PlannedShot planned =
            bot::planCarom(verifier, balls, game, {budget, noise, samples});
        plan_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        bot::PlannedShot noisy = planned;
        noisy.cue = bot::perturbed(planned.cue, noise, rng);
        const bot::Trial t = verifier.run(balls, game, noisy);
        ++strokes;
        if (!t.judged || t.verdict.scored == 0) break;
        ++points;
        balls = t.after;
        game = t.verdict.next;
      }
    }
  }
  const double per_inning = static_cast<double>(points) / innings;
  state.counters["points_per_inning"] = per_inning;
  std::sort(plan_ms.begin(), plan_ms.end());
  std::printf(
      "three-cushion, olympiad noise, %d samples a scoring stroke, %d trials a turn: %d points in "
      "%d innings (%.2f an inning), %d strokes; planning p50 %.0f ms\n",
      samples, budget, points, innings, per_inning, strokes,
      plan_ms.empty() ? 0.0 : plan_ms[plan_ms.size() / 2]);
}
BENCHMARK(BM_CaromInnings)
    ->Args({0, 320})
    ->Args({8, 320})
    ->Args({8, 2000})
    ->Args({16, 2000})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  pool::bench::CheckedReporter reporter;
  return pool::bench::runBenchmarks(argc, argv, reporter);
}
