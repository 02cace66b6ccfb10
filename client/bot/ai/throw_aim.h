// Aiming off for throw: a pot's cue line turned so the object ball leaves where the physics sends
// it (friction between the balls, the cue ball's speed and spin), not where the ghost ball says.
#pragma once

#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/plan_context.h"

namespace pool::bot {

/// Turns `shot` (a stroke along `line`) so that `line`'s ball leaves along the line from the ghost
/// ball through it. One short probe of the physics (ShotVerifier::heading: a second or two of
/// play at most, not the whole shot) measures how far off it leaves; the cue line turns by that
/// error over the geometry's rate (contactLine): cut-induced throw is a few degrees at most and
/// changes little over so small a turn. Unchanged when the probe finds no clean first contact or
/// the budget is spent.
void aimForThrow(PlanContext& context, PlannedShot& shot, const PotLine& line);

}  // namespace pool::bot
