// The WPA 8-ball rule set: checks a shooter's intent, judges a shot, applies the choices it offers.
#pragma once

#include <cstdint>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/table_context.h"
#include "rules/verdict.h"

namespace pool::rules {

/// Standard: every shot after the break is called (ball and pocket) or declared a safety.
/// Casual: only the 8 is called; any ball of the shooter's group (any but the 8 on an open table)
/// that falls on a legal shot keeps the turn.
enum class CallMode : std::uint8_t { Standard, Casual };

const char* toString(CallMode mode);

/// Options of a match.
struct EightBallConfig {
  CallMode calls = CallMode::Standard;
  /// A stalemate (re-rack, same breaker) after this many consecutive shots that pocket no
  /// object ball; 0: only by agreement (agreeStalemate).
  int stalemate_turns = 40;
};

/// Object balls on the table (in `balls`) that the shooter may hit first: any on the break; any
/// but the 8 on an open table; the shooter's group, or the 8 once the group is cleared.
std::vector<int> legalFirstBalls(const GameState& state, const std::vector<physics::Ball>& balls);

/// True when the shooter's group is assigned and none of it is on the table: the 8 is next.
bool onTheEight(const GameState& state, const std::vector<physics::Ball>& balls);

/// Checks a declared intent before the shot. Refused: the game is over; options are pending and
/// none (or one not offered) is chosen, or the choice changes the table (use applyChoice first);
/// a choice when none is pending; a call and a safety at once; a called ball not on the table,
/// not 1–15, or not the shooter's to call; an unknown pocket; no call and no safety (Standard,
/// after the break); the 8 uncalled when it is the shooter's ball (Casual).
Check<> checkIntent(const GameState& state, const Intent& intent,
                    const std::vector<physics::Ball>& balls, const EightBallConfig& config = {});

/// Judges one shot. Refused (never judged) when the intent fails checkIntent, the cue ball in
/// hand was placed illegally, or the shot fails checkShot. A shot clock that ran out with no
/// strike (empty log) is judged as a foul without a shot.
Result<Verdict> judgeEightBall(const GameState& state, const Shot& shot, const TableContext& table,
                               const EightBallConfig& config = {});

/// Applies the choice of a pending option without a shot. `balls`: the table now (the 8's
/// re-spot point is found among them). The verdict's respots/rerack say what to do to the table.
Result<Verdict> applyChoice(const GameState& state, Choice choice,
                            const std::vector<physics::Ball>& balls, const TableContext& table);

/// Both players agree the game is stalemated: re-rack, the same breaker breaks.
Result<Verdict> agreeStalemate(const GameState& state);

/// `loser` concedes or is forfeited: the other seat wins.
Verdict forfeit(const GameState& state, int loser);

}  // namespace pool::rules
