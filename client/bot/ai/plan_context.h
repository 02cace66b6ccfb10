// What every part of the planner shares for one turn: the table, the physics trials and their
// budget, the rules state to judge with and the answer to pending options.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/leave_value.h"
#include "client/bot/ai/planned_shot.h"
#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/table_view.h"
#include "physics/ball.h"
#include "rules/game_state.h"

namespace pool::bot {

/// How widely a turn's pots are searched.
struct PotBreadth {
  int lines = 10;     ///< pot lines tried in the physics, easiest first
  int variants = 12;  ///< strokes (speed, spin, side) tried on each line, at most pot_search.h's 48
  int shortlist = 8;  ///< the pots worth most in exact trials, then sampled under the noise
  bool banks = false;  ///< one-cushion banks (bank_shot.h) after the direct lines from the lie
};

/// What a foul costs in a stroke's worth (a clean pot with a hopeless leave is worth 100).
inline constexpr double kFoulCost = 40.0;

/// One turn's planning inputs.
struct PlanContext {
  const TableView& view;
  ShotVerifier& verifier;
  std::vector<physics::Ball> balls;     ///< the layout at rest, every ball
  rules::GameState judge_state;         ///< the rules state as it stands (options pending included)
  rules::GameState play_state;          ///< the state once the chosen option applies
  std::optional<rules::Choice> choice;  ///< the answer carried with the shot
  int runs_left = 0;                    ///< physics trials still allowed this turn
  ExecutionNoise noise{};               ///< the bot's own execution error, sampled to judge shots
  int samples = 0;                      ///< noisy trials a shortlisted pot gets (0: exact only)
  double leave_weight = 0.0;            ///< what a sure pot next adds to a clean pot's 100
  LookAhead look_ahead = LookAhead::NextShot;  ///< how far a leave is looked at
  PotBreadth breadth{};                        ///< how widely pots are searched
  Rng rng{kPlanSeed};                          ///< the samples' draws (a fixed seed: plans repeat)

  static constexpr std::uint64_t kPlanSeed = 0x5eedULL;

  /// Runs `shot` if the budget allows; empty when it is spent.
  std::optional<Trial> tryShot(const PlannedShot& shot);
  /// ShotVerifier::heading if the budget allows (a probe costs a trial); empty when it is spent.
  std::optional<Vec2> probeHeading(const PlannedShot& shot, int id, double horizon);
  /// Runs `shot` as the bot would play it: its stroke moved by one draw of `noise`.
  std::optional<Trial> tryNoisy(const PlannedShot& shot);
  /// The mean of `worth` over `tries` noisy tries of `shot` (tryNoisy); empty when the budget
  /// runs out first.
  std::optional<double> meanOfNoisy(const PlannedShot& shot, int tries,
                                    const std::function<double(const Trial&)>& worth);
  /// What a stroke that keeps the turn is worth, 100 for the stroke and up to `leave_weight` more
  /// for its leave (leaveValue, graded with the bot's own aim error, or a strong player's when it
  /// expects none of itself).
  double keptTurnWorth(const Trial& trial) const;
  /// A shot skeleton carrying the turn's choice.
  PlannedShot blank(ShotKind kind) const;
  /// The legal object balls for the shooter (legalFirstBalls on play_state).
  std::vector<int> legalBalls() const;
  /// The legal balls the cue ball may hit first straight from where it lies or is placed: with
  /// ball in hand behind the head string, not those behind it too (a foul played directly:
  /// rules::Foul::BehindHeadStringDirect).
  std::vector<int> directBalls() const;
};

/// How good a layout is for the player to shoot in `state`: 1 with the cue ball in hand, else
/// 1 / (1 + difficulty) of the easiest clear pot line, 0 when none (or the game is over).
double shooterChances(const std::vector<physics::Ball>& balls, const rules::GameState& state,
                      const TableView& view);

/// A cue shot along `yaw` at ball speed `speed` (m/s) with tip height `tip` (fraction of R).
physics::CueShot stroke(double yaw, double speed, double tip = 0.0);

}  // namespace pool::bot
