// The bot's cue as watchers see it while it thinks: it swings onto the planned heading, then draws
// back for the planned power, so a bot's turn looks like a player's aim.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "client/bot/ai/planned_shot.h"
#include "physics/ball.h"
#include "protocol/aim_sample.h"

namespace pool::bot {

/// The cue of `shot` after `progress` (0–1) of the think time: for the first 70 % the heading
/// glides (eased) from 0.35 rad to the left onto the planned one, then the cue draws back to the
/// planned power; tip and elevation as planned; the cue ball where it lies in `balls` (or where
/// the shot places it). Only the cue's values are filled in (not match, seat or numbers).
protocol::AimSample thinkingAim(const PlannedShot& shot, const std::vector<physics::Ball>& balls,
                                double progress);

/// The draw-back (0–1) the window's power bar would show for `shot`'s speed.
double powerOf(const PlannedShot& shot);

}  // namespace pool::bot
