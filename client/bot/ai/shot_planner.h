// The bot's brain for one turn: from the layout at rest and the rules state to a planned shot.
#pragma once

#include <vector>

#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/leave_value.h"
#include "client/bot/ai/plan_context.h"
#include "client/bot/ai/planned_shot.h"
#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/table_view.h"
#include "physics/ball.h"
#include "rules/game_state.h"

namespace pool::bot {

/// Limits of one turn's search.
struct PlannerOptions {
  int max_runs = 320;  ///< physics trials per turn, at most
  /// The execution error the planner expects of its own stroke: each shortlisted pot is played
  /// `samples` times under it and chosen by what it is worth on average (0 samples: judged by
  /// one exact trial, as a flawless player would).
  ExecutionNoise noise{};
  int samples = 0;
  /// What a leave sure to offer a pot next adds to a clean pot's worth of 100. A leave is graded
  /// by the chance that at least one of its three most makeable balls would go in under `noise`
  /// (a strong player's aim error when `noise` is none). Position counts for more than the pot,
  /// as for a player running a rack (bot_bench, 8-ball under the olympiad noise, 100 racks:
  /// break-and-runs 8 % at 200, 12 % at 400, 9 % at 800).
  double leave_weight = 400.0;
  /// How far a leave is looked at (leave_value.h).
  LookAhead look_ahead = LookAhead::NextShot;
  /// How many lines, strokes a line and sampled pots a turn looks at.
  PotBreadth breadth{};
};

/// Chooses shots on one table. Pure apart from the physics trials it runs: the same layout and
/// state give the same shot.
class ShotPlanner {
 public:
  explicit ShotPlanner(const TableView& view, PlannerOptions options = {});

  /// The shot for the shooter of `state` on the layout `balls` (every ball, pocketed ones too):
  /// the break; else, after answering pending options, the best verified pot (from the cue ball,
  /// or from a chosen spot when in hand); else the best verified safety; else a fallback hit.
  /// Three-cushion: the carom search's stroke (carom_search.h).
  PlannedShot plan(const std::vector<physics::Ball>& balls, const rules::GameState& state);

  /// Physics trials run so far (all turns).
  int runs() const { return verifier_.runs(); }

 private:
  const TableView& view_;
  PlannerOptions options_;
  ShotVerifier verifier_;
};

/// The option the bot takes among `options` (ball in hand, else play on, else re-break), or empty
/// when none is pending.
std::optional<rules::Choice> chooseOption(const std::vector<rules::Choice>& options);

}  // namespace pool::bot
