// The 8-ball rule set's own steps of judging a shot: the break and the play (internal).
#pragma once

#include "rules/eight_ball.h"
#include "rules/shot_facts.h"
#include "rules/verdict_steps.h"

namespace pool::rules::detail {

/// The opening break (phase Break).
Judged judgeBreak(const GameState& state, const Shot& shot, const ShotFacts& facts);

/// Any shot after the break.
Judged judgePlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                 const TableContext& table, const EightBallConfig& config);

}  // namespace pool::rules::detail
