// Safeties: when nothing is on, a legal hit that leaves the opponent the least to shoot at.
#pragma once

#include <optional>
#include <vector>

#include "client/bot/ai/plan_context.h"

namespace pool::bot {

/// The best verified safety from the cue ball where it lies, or from one of `spots` when it is in
/// hand: legal (first contact on a legal ball, a cushion after), not losing, scored by how little
/// the opponent is left. Empty when none of the tried hits is legal.
std::optional<PlannedShot> searchSafety(PlanContext& context, const std::vector<Vec2>& spots);

/// The last resort: a declared safety, full on the nearest legal ball (any ball if none is
/// legal) at a medium pace, from the cue ball or from `spot` when in hand.
PlannedShot fallbackShot(const PlanContext& context, const std::optional<Vec2>& spot);

}  // namespace pool::bot
