// The opening break: the cue ball behind the head string, full on the apex ball, hard.
#pragma once

#include <optional>

#include "client/bot/ai/plan_context.h"

namespace pool::bot {

/// Ball speed of the break, m/s.
inline constexpr double kBreakSpeed = 9.0;

/// The best of a few break positions tried in the physics: a legal break that keeps the cue ball,
/// ideally with a ball down. Always returns a shot (the first spot when none verified).
PlannedShot planBreak(PlanContext& context);

}  // namespace pool::bot
