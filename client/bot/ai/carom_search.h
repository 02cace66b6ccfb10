// Three-cushion for the bot: a search over strokes with the physics for the one most likely to
// score (both object balls, three cushions before the second).
#pragma once

#include <vector>

#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/planned_shot.h"
#include "client/bot/ai/shot_verifier.h"
#include "physics/ball.h"
#include "rules/game_state.h"

namespace pool::bot {

/// How hard the carom search looks.
struct CaromSearchOptions {
  int max_runs = 320;  ///< physics trials per turn, at most
  /// The planner's own execution error: the scoring strokes found are replayed `samples` times
  /// under it and the one that scores most often is played (0: the first found, judged exactly).
  ExecutionNoise noise{};
  int samples = 0;
};

/// The stroke for the shooter of `state` (who strikes rules::caromBallOf's ball): a sweep of
/// headings round the shooter's ball at three speeds with running and reverse side (the ball
/// driven round the table by its side spin, as players do), each tried in the physics and judged
/// by the rules; scoring strokes are refined by half-steps of heading and, with `samples`, ranked
/// by how often they score under `noise`. No point found: the legal stroke that keeps the shooter's
/// ball nearest the middle of the table (the opponent's next shot the least helped by a cushion
/// lie is beyond this search). The opening must hit the red first: only such strokes count.
PlannedShot planCarom(ShotVerifier& verifier, const std::vector<physics::Ball>& balls,
                      const rules::GameState& state, const CaromSearchOptions& options);

}  // namespace pool::bot
