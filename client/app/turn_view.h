// Where a turn starts looking: the cue aimed from the cue ball at the nearest ball the shooter may
// hit first (the rack's apex on the break), so each turn opens on a shot and not sideways.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "physics/ball.h"
#include "rules/game_rules.h"
#include "rules/game_state.h"

namespace pool::app {

/// The heading (rad, 0 = +x) from `cue` (table plane, m) to the centre of the nearest object ball
/// on the table that `state` lets the shooter hit first in `game` (rules::firstBallsFor: the
/// group or the 8 in 8-ball, the lowest ball in 9- and 10-ball), or to the nearest object ball
/// on the table when none is legal; empty when no object ball is on it.
std::optional<double> turnStartYaw(const Eigen::Vector2d& cue,
                                   const std::vector<physics::Ball>& balls,
                                   const rules::GameState& state, rules::Game game);

}  // namespace pool::app
