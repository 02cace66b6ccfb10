// One judging pipeline for every game, with each game's own steps plugged in (internal).
#pragma once

#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/shot_facts.h"
#include "rules/table_context.h"
#include "rules/verdict.h"
#include "rules/verdict_steps.h"

namespace pool::rules::detail {

/// A game's own steps of judging a shot. judgeWith calls them between the steps every game
/// shares; a new game implements this.
class Referee {
 public:
  virtual ~Referee() = default;

  /// Refuses a declared intent the game does not allow (a missing call, an unoffered choice).
  virtual Check<> checkIntent(const GameState& state, const Intent& intent,
                              const std::vector<physics::Ball>& balls) const = 0;
  /// The state the shot is played from once a choice made with it applies.
  virtual GameState stateForShot(const GameState& state, const Intent& intent) const = 0;
  /// The opening break (phase Break).
  virtual Judged judgeBreak(const GameState& state, const Shot& shot, const ShotFacts& facts,
                            const TableContext& table) const = 0;
  /// Any shot after the break.
  virtual Judged judgePlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                           const TableContext& table) const = 0;
  /// True where a player's third foul in a row loses the rack.
  virtual bool threeFoulsLose() const = 0;
  /// Shots in a row without a ball down before the rack is replayed; 0: never.
  virtual int stalemateTurns() const = 0;
};

/// Judges one shot by `referee`'s game: the intent, the cue ball in hand, the clock, the shot's
/// facts, the game's break or play, the balls the watchdog removed, fouls in a row, re-spots, the
/// stalemate and the next state, in that order.
Result<Verdict> judgeWith(const Referee& referee, const GameState& state, const Shot& shot,
                          const TableContext& table);

}  // namespace pool::rules::detail
