// The bank aim aid: the cue ball's path along the cue reflected off the cushions (angle in equals
// angle out), to the first ball it meets or its last cushion, as three-cushion players and kick
// shots need.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "game/loaded_table.h"
#include "physics/ball.h"

namespace pool::app {

/// The cushions a bank path follows: three in three-cushion, two for a kick in the other games.
inline constexpr int kCaromBankCushions = 3;
inline constexpr int kKickBankCushions = 2;

/// A cue ball's centre line off the cushions (table plane, m).
struct BankPath {
  std::vector<Eigen::Vector2d> points;  ///< from the cue ball, each cushion met, then the end
  int cushions = 0;                     ///< cushions met on the way
  std::optional<int> ball;              ///< the ball it meets at the end; empty: none
};

/// The path of the ball at `cue` (m) sent along `yaw` (rad): straight to a cushion (its centre a
/// radius inside the playing surface, as predictAim's), mirrored there, and on, until it meets a
/// ball of `balls` on the table other than `struck` (the end: its centre where they touch) or
/// has met `cushions` cushions (the end: `tail` m on from the last). The mirror is the geometry
/// alone: no spin, speed or cushion height bends it, which is what a diamond system starts from.
BankPath bankPath(const Eigen::Vector2d& cue, double yaw, const std::vector<physics::Ball>& balls,
                  const game::LoadedTable& view, int struck, int cushions, double tail);

}  // namespace pool::app
