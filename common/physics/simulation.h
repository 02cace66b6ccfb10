// One shot from strike to rest: the event loop that steps the ODE world between events.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/result.h"
#include "physics/ball.h"
#include "physics/cue_strike.h"
#include "physics/events.h"
#include "physics/profile.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::physics {

/// How far to run and what to record.
struct SimOptions {
  double max_time = 60.0;  ///< bound on simulated time, s
  double sample_hz = 0.0;  ///< > 0: record every ball at exactly t = k / sample_hz
  bool profile = false;    ///< time the engine's parts into SimStats::seconds (benchmarks)
};

/// Every ball at one instant.
struct Sample {
  double t = 0.0;
  std::vector<Ball> balls;
};

/// Counters for benchmarks and diagnostics (not part of any output contract).
struct SimStats {
  std::uint64_t steps = 0;         ///< ODE world steps taken (table)
  std::uint64_t pocket_steps = 0;  ///< ODE steps of balls falling in the pockets and trough
  std::uint64_t events = 0;
  PartTimes seconds{};  ///< CPU-side time by part (Part), when SimOptions::profile is set
};

/// What a shot did.
struct ShotOutcome {
  EventLog events;                 ///< in time order
  std::vector<Ball> balls;         ///< every ball, pocketed ones too, at the end
  std::optional<double> t_rest;    ///< when the last ball on the table stopped; empty if truncated
  bool truncated = false;          ///< max_time came first
  std::vector<Sample> trajectory;  ///< when sample_hz > 0
  SimStats stats;
};

/// Checks balls for placement on a table: ids in 0..15 and each once, no two overlapping, each
/// centre on the slate (not inside a cushion, not over a pocket hole). Refuses with a one-line
/// reason naming the ball, e.g. "ball 3 overlaps ball 5" ("overlap"), "ball 2 is off the slate"
/// ("off_slate").
Check<> checkPlacement(const std::vector<Ball>& balls, const table::TableGeometry& geometry,
                       const table::PhysicsParams& params);

/// A table with its balls, stepping ODE with our cloth, ball and cushion models. Deterministic:
/// the same inputs give bit-identical outputs on the same build.
class Simulation {
 public:
  Simulation(const table::TableSpec& spec, const table::TableGeometry& geometry);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Places balls (any state; usually at rest on the slate). Fails on ids out of 0..15 or twice,
  /// overlapping balls, or a ball off the slate, with a reason naming the ball.
  Result<bool> setBalls(const std::vector<Ball>& balls);

  /// Strikes the cue ball (id 0) and runs until every ball on the table is at rest, or max_time.
  Result<ShotOutcome> shoot(const CueShot& shot, const SimOptions& options = {});

  /// Runs from the current state without a strike (for balls set in motion by setBalls).
  ShotOutcome run(const SimOptions& options = {});

  const std::vector<Ball>& balls() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pool::physics
