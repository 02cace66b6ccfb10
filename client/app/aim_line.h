// The aim line: where the cue ball, sent straight along the cue, first touches a ball or a
// cushion, where that ball heads, and the call that follows from it; what a click may call.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "client/app/aim.h"
#include "client/app/controls.h"
#include "game/loaded_table.h"
#include "physics/ball.h"
#include "rules/game_rules.h"
#include "rules/game_state.h"

namespace pool::app {

/// The straight-line prediction of one aim (table plane, m).
struct AimPrediction {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();     ///< cue ball centre
  Eigen::Vector2d contact = Eigen::Vector2d::Zero();  ///< cue ball centre at its first contact
  std::optional<int> ball;                            ///< the first ball touched; empty: a cushion
  Eigen::Vector2d object_dir = Eigen::Vector2d::Zero();  ///< unit: that ball's heading
  int pocket = -1;  ///< index into LoadedTable::pockets the ball heads closest to; -1: none
};

/// Distance along unit `dir` from `from` to where a point comes within `reach` of `centre`;
/// infinity when it never does ahead (a ball's centre sweeping toward another's: reach 2R).
double sweep(const Eigen::Vector2d& from, const Eigen::Vector2d& dir, const Eigen::Vector2d& centre,
             double reach);

/// Where the cue ball at `cue` (m) heading along `yaw` (rad) first touches another ball on the
/// table in `balls` (centres 2R apart) or a cushion (its centre R inside the playing surface).
/// `struck`: the ball at `cue` (the cue ball; in three-cushion the shooter's own).
AimPrediction predictAim(const Eigen::Vector2d& cue, double yaw,
                         const std::vector<physics::Ball>& balls, const game::LoadedTable& view,
                         int struck = physics::kCueBall);

/// The call for `aim` in `state` of `game`: none on the break, none in 9-ball (it needs no
/// call), three-cushion or snooker (the colour hit first is the one nominated); else the first ball
/// touched and the pocket it heads for when that ball is the shooter's to hit first
/// (rules::firstBallsFor); otherwise a safety.
ShotCall autoCall(const AimPrediction& aim, const rules::GameState& state,
                  const std::vector<physics::Ball>& balls, const game::LoadedTable& view,
                  rules::Game game);

/// What a click may call at `game`: every object ball on the table but `struck` (a practice table
/// drags them too) and every pocket's mouth; snooker's no pocket (it calls none).
ClickTargets clickTargetsFor(rules::Game game, const std::vector<physics::Ball>& balls, int struck,
                             const game::LoadedTable& view);

/// Snooker's nomination from `state`: the balls on the table the rules let the shooter nominate
/// (rules::checkIntentFor: a colour when on one, any object ball with a free ball, none
/// otherwise); empty for the other games, which call a ball in a pocket.
std::optional<std::vector<int>> nominableFor(rules::Game game, const rules::GameState& state,
                                             const std::vector<physics::Ball>& balls);

}  // namespace pool::app
