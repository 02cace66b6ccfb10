// The steps every rule set builds its verdicts from: turn, end, re-rack, clock (internal).
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

namespace pool::rules::detail {

/// A verdict still being built, with the balls to put back (positions found at the end).
struct Judged {
  Verdict verdict;
  std::vector<int> respot_ids;
};

/// True when `id` is listed in `balls` and on the table.
bool ballOnTable(int id, const std::vector<physics::Ball>& balls);

/// The turn passes to the opponent with `in_hand`.
void passTurn(const GameState& state, BallInHand in_hand, Verdict& verdict);

/// The game ends for `end`: the shooter wins on EightPocketed, otherwise the opponent.
void endGame(const GameState& state, GameEnd end, Verdict& verdict);

/// The choice that re-racks: `breaker` breaks the new rack.
Verdict rerackVerdict(int breaker);

/// The choices that keep the rack: the chooser shoots with `in_hand`.
Verdict playOnVerdict(const GameState& state, BallInHand in_hand);

/// Refuses a cue ball in hand (per `state`) placed where the rules do not allow it.
Check<> checkCueInHand(const GameState& state, const Shot& shot, const TableContext& table);

/// Balls the watchdog removed: object balls go back on the table, the cue ball comes in hand.
void addWatchdogRemovals(const ShotFacts& facts, Judged& judged);

/// Fouls any shot can make whatever was hit: the cue ball or an object ball leaving play, the
/// clock.
std::vector<Foul> leavingFouls(const Shot& shot, const ShotFacts& facts);

/// Lack of progress: after `stalemate_turns` (> 0) shots in a row with no ball down the rack is
/// replayed by the same breaker.
void checkStalemate(const GameState& state, int dry_turns, int stalemate_turns, Verdict& v);

/// The clock ran out before the strike: a foul without a shot, ball in hand anywhere to the
/// opponent. On the break the other player breaks (the rack stands: "re-racking" it only hands the
/// break over).
Judged timeOut(const GameState& state);

/// The state after a verdict; `dry_turns` is the updated count of shots without a ball down.
GameState nextState(const GameState& state, const Verdict& verdict, int dry_turns);

}  // namespace pool::rules::detail
