// Pieces shared by the files of the 9-ball and 10-ball rule set (not part of the public API).
#pragma once

#include <vector>

#include "rules/eight_ball_detail.h"
#include "rules/rotation.h"
#include "rules/shot_facts.h"

namespace pool::rules::detail {

/// The rotation break (phase Break).
Judged judgeRotationBreak(const GameState& state, const Shot& shot, const ShotFacts& facts,
                          const RotationConfig& config);

/// Any shot after the break, a push-out included.
Judged judgeRotationPlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                         const RotationConfig& config);

/// A foul: the opponent has the cue ball in hand anywhere and no choice to make.
void rotationFoul(const GameState& state, Verdict& verdict);

}  // namespace pool::rules::detail
