// Where re-spotted balls go: the foot spot, or the nearest free point behind it on the long string.
#pragma once

#include <vector>

#include "physics/ball.h"
#include "rules/table_context.h"
#include "rules/verdict.h"

namespace pool::rules {

/// Places `ids` one after another with table::respotPosition, among the balls on the table in
/// `balls` (their final state) and the ones already placed. Balls of `ids` still listed on the
/// table in `balls` do not count as occupying a point.
std::vector<Respot> respotBalls(const std::vector<int>& ids,
                                const std::vector<physics::Ball>& balls, const TableContext& table);

}  // namespace pool::rules
