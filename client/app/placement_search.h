// Ball in hand starts at a legal spot: the nearest place to a wanted one that the rules accept.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/table_context.h"

namespace pool::app {

/// The legal placement of the cue ball in hand (`in_hand`) nearest to `wanted` (table plane, m)
/// among `wanted` itself and the points of a grid of half-radius steps around it, up to
/// `max_distance` away; empty when none is legal.
std::optional<Eigen::Vector2d> nearestLegalPlacement(rules::BallInHand in_hand,
                                                     const Eigen::Vector2d& wanted,
                                                     const std::vector<physics::Ball>& balls,
                                                     const rules::TableContext& table,
                                                     double max_distance = 0.6);

}  // namespace pool::app
