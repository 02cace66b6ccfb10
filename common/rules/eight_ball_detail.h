// Pieces shared by the files of the 8-ball rule set (not part of the public API).
#pragma once

#include <vector>

#include "physics/ball.h"
#include "rules/eight_ball.h"
#include "rules/shot_facts.h"

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

/// The opening break (phase Break).
Judged judgeBreak(const GameState& state, const Shot& shot, const ShotFacts& facts);

/// Any shot after the break.
Judged judgePlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                 const TableContext& table, const EightBallConfig& config);

/// The state after a verdict; `dry_turns` is the updated count of shots without a ball down.
GameState nextState(const GameState& state, const Verdict& verdict, int dry_turns);

}  // namespace pool::rules::detail
