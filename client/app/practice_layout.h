// A practice table's changes from the window: the layout a dragged ball's Layout command sends,
// and the rack a re-rack key asks for.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "physics/ball.h"
#include "protocol/practice_request.h"
#include "rules/game_rules.h"
#include "rules/table_context.h"

namespace pool::app {

/// Every ball on the table where it lies and ball `id` at `at`; a cue ball that has left the
/// table (a scratch) comes back to the head spot, or the nearest free point to it, since a layout
/// without the cue ball is refused.
std::vector<protocol::BallSpot> layoutWithMove(const std::vector<physics::Ball>& balls, int id,
                                               const Eigen::Vector2d& at,
                                               const rules::TableContext& table);

/// The rack (a game's number, the Rack command's) that a re-rack key asking for `asked` (8, 9 or
/// 10: keys 8, 9, 0) racks at a practice table of `table_game`: `asked` at a pool table; at a
/// table of a game of its own (snooker, three-cushion) that game, whichever key (the server racks
/// only the games of the table it is).
int practiceRack(rules::Game table_game, int asked);

}  // namespace pool::app
