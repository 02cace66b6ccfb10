// The 9- and 10-ball rule set's own steps of judging a shot: break, play, foul (internal).
#pragma once

#include "rules/rotation.h"
#include "rules/shot_facts.h"
#include "rules/verdict_steps.h"

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
