// Tries a planned shot in the real physics on a copy of the table and has the rules judge it.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "client/bot/ai/planned_shot.h"
#include "client/bot/ai/table_view.h"
#include "physics/ball.h"
#include "physics/simulation.h"
#include "rules/game_state.h"
#include "rules/verdict.h"

namespace pool::bot {

/// What a shot would do.
struct Trial {
  bool judged = false;  ///< the physics ran and the rules judged it
  std::string error;    ///< why not, when !judged
  rules::Verdict verdict;
  std::vector<physics::Ball> after;  ///< every ball at rest, respots applied
  bool potted_call = false;          ///< the called ball dropped in the called pocket
  bool wins = false;                 ///< the game ends with the shooter winning
  bool loses = false;                ///< the game ends with the shooter losing
  /// The physics would refuse the layout it leaves (e.g. a ball at rest in a pocket mouth, past
  /// the nose line): the next shot could not be played, so the planner avoids such shots.
  bool dead_layout = false;
  Eigen::Vector2d cue_end = Eigen::Vector2d::Zero();  ///< where the cue ball stops (if on table)
};

/// Runs shots on one simulation of the view's table. Deterministic for the same inputs.
class ShotVerifier {
 public:
  explicit ShotVerifier(const TableView& view);

  /// `shot` from the layout `balls` (every ball, pocketed ones too) with the rules in `state`.
  Trial run(const std::vector<physics::Ball>& balls, const rules::GameState& state,
            const PlannedShot& shot);

  /// The unit direction ball `id` leaves in when `shot`'s cue ball first strikes it (throw and
  /// all), read from where it is at its first event after the strike (or at `horizon`, where the
  /// physics stops): empty when the cue ball meets another ball first or has not struck it by
  /// then.
  std::optional<Eigen::Vector2d> heading(const std::vector<physics::Ball>& balls,
                                         const PlannedShot& shot, int id, double horizon);

  /// Shots run so far.
  int runs() const { return runs_; }

 private:
  const TableView& view_;
  physics::Simulation simulation_;
  int runs_ = 0;
};

/// `balls` with the cue ball placed at `at` (at rest on the slate), added if missing.
std::vector<physics::Ball> withCueBallAt(const std::vector<physics::Ball>& balls,
                                         const Eigen::Vector2d& at, double radius);

/// `balls` with the verdict's re-spotted balls put back at rest.
std::vector<physics::Ball> withRespots(std::vector<physics::Ball> balls,
                                       const rules::Verdict& verdict, double radius);

}  // namespace pool::bot
