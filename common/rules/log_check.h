// Refuses a shot whose event log or final balls contradict themselves or the table before the shot.
#pragma once

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/shot.h"

namespace pool::rules {

/// Checks a shot before it is judged. Refused, with a one-line reason naming the ball and time:
/// balls before that repeat an id, lack the struck ball or use an id outside 0–21; an empty log; a
/// log that does not start with the strike of `struck` (the cue ball; in three-cushion the
/// shooter's own ball), or strikes twice; times not finite or out of
/// order; an event naming a ball that was not on the table; a ball hitting itself; an unknown
/// pocket; a ball pocketed (or off the table) twice, or touching anything after; a ball reaching
/// a cushion, a pocket or the air without having been set in motion; two resting balls colliding;
/// any event once every ball came to rest (except the end of a spin or a watchdog re-spot); final
/// balls that disagree with the log. A watchdog re-spot (Respot) excuses a ball's final state.
Check<> checkShot(const Shot& shot, int struck = physics::kCueBall);

}  // namespace pool::rules
