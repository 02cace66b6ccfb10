// Finds the best pot: ranks ghost-ball lines, then tries the easiest in the physics at a few
// speeds and spins and keeps the one that pockets the called ball legally with the best leave.
#pragma once

#include <optional>
#include <vector>

#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/plan_context.h"

namespace pool::bot {

/// A pot line, and where the cue ball is placed first when it is in hand.
struct PotCandidate {
  PotLine line;
  std::optional<Vec2> place;
};

/// The strokes (speed, spin and side) the search knows for a line.
inline constexpr int kMaxVariants = 48;

/// The best verified pot among `candidates` (easiest first), or empty when none pockets the
/// called ball legally while keeping the turn (or wins the game). The call and the placement of
/// the winning candidate are in the returned shot.
std::optional<PlannedShot> searchPots(PlanContext& context,
                                      const std::vector<PotCandidate>& candidates);

/// The candidates from the cue ball where it lies.
std::vector<PotCandidate> potsFromLie(const PlanContext& context);

}  // namespace pool::bot
