// A practice table's layout after the player drags a ball: what the table's Layout command sends.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "physics/ball.h"
#include "protocol/practice_request.h"
#include "rules/table_context.h"

namespace pool::app {

/// Every ball on the table where it lies and ball `id` at `at`; a cue ball that has left the
/// table (a scratch) comes back to the head spot, or the nearest free point to it, since a layout
/// without the cue ball is refused.
std::vector<protocol::BallSpot> layoutWithMove(const std::vector<physics::Ball>& balls, int id,
                                               const Eigen::Vector2d& at,
                                               const rules::TableContext& table);

}  // namespace pool::app
