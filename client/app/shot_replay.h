// A stored shot played again from its layouts and event log alone (no simulation): each ball's
// path rebuilt through the positions its events record, timed as the cloth slows a ball.
#pragma once

#include <vector>

#include "physics/ball.h"
#include "physics/events.h"
#include "table/physics_params.h"

namespace pool::app {

/// The table at one instant of a replayed shot, `t` seconds after the strike.
struct ReplayFrame {
  double t = 0.0;
  std::vector<physics::Ball> balls;  ///< every ball of the layout, in its order
};

/// The frames of a stored shot every 1/`hz` s from the strike until the last ball stops (the
/// last frame is `after` itself), built from:
/// - `before`: the table at the strike; `after`: the table at rest (pocketed balls off it);
/// - `events`: the shot's log. Each event puts its ball_a exactly at its `pos` at its time; a
///   ball struck by another (ball_b) is where its own track puts it, moved to touch ball_a.
/// Between two of a ball's events it moves along the straight line joining them: with the
/// constant deceleration of its phase (u_s·g sliding after a strike or an impact, unless it could
/// not have slid that far and still be moving: then it rolled; u_r·g rolling after slide_to_roll;
/// a ball that stops next slows to rest evenly), on a parabola between
/// airborne and land, and turning as a ball rolling on the cloth turns, so that it arrives in
/// `after`'s orientation. A path that sliding spin bends is drawn as its chord: a ball is exactly
/// where the log says at each of its events and close to its true path between them.
/// A ball leaves the table (pocketed, or off it) at its pocket or off_table event, for where
/// `after` has it.
std::vector<ReplayFrame> replayFrames(const std::vector<physics::Ball>& before,
                                      const physics::EventLog& events,
                                      const std::vector<physics::Ball>& after, double hz = 60.0,
                                      const table::PhysicsParams& params = {});

}  // namespace pool::app
