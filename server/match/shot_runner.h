// Simulates one shot on a match's table: the balls on the table go in, events and frames come out.
#pragma once

#include <memory>
#include <vector>

#include "core/result.h"
#include "game/loaded_table.h"
#include "physics/simulation.h"

namespace pool::server {

/// Runs shots on one table. Holds one physics world, so it serves one shot at a time; the matches
/// of a server share it (their shots run one after another on the server's loop).
class ShotRunner {
 public:
  explicit ShotRunner(std::shared_ptr<const game::LoadedTable> kit);

  /// Strikes the cue ball of `balls` with `cue` and runs to rest (at most `max_time` s of
  /// simulated time), sampling every ball at k / `sample_hz` s. Balls already off the table
  /// (pocketed, flown off) stay out of the world and come back unchanged in the outcome's
  /// `balls` and in every trajectory sample, which list every ball of `balls` in id order.
  /// Fails on a layout the physics refuses or a strike it cannot make.
  Result<physics::ShotOutcome> run(const std::vector<physics::Ball>& balls,
                                   const physics::CueShot& cue, double sample_hz, double max_time);

  const game::LoadedTable& kit() const { return *kit_; }

 private:
  std::shared_ptr<const game::LoadedTable> kit_;
  physics::Simulation simulation_;
};

}  // namespace pool::server
