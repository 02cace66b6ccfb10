// Checks a ball's placement before a shot (cue ball in hand, practice re-placing): refused with a
// reason.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/table_context.h"

namespace pool::rules {

/// Why a placement is refused.
enum class PlacementProblem : std::uint8_t {
  None,                 ///< the placement is fine
  NoBallInHand,         ///< the shooter does not have the cue ball in hand
  NotFinite,            ///< a coordinate is NaN or infinite
  OffSlate,             ///< the ball would not lie wholly on the playing surface
  OverPocket,           ///< the ball's centre would be over a pocket hole
  Overlaps,             ///< it would overlap another ball on the table
  NotBehindHeadString,  ///< in hand behind the head string, but its centre is at x >= head string x
  NotInTheD,            ///< snooker: in hand in the D, but its centre is outside it
};

const char* toString(PlacementProblem problem);

/// The outcome of a placement check: its problem and one line, e.g. "the ball would overlap ball
/// 5".
using PlacementCheck = Check<PlacementProblem>;

/// Ball `id` placed at `pos` (table plane, m): on the slate (its centre at least one radius inside
/// the cushion noses), not over a pocket hole (when the context has holes), and not overlapping
/// any other ball on the table in `balls` (its own entry, if any, is ignored).
PlacementCheck checkBallPlacement(int id, const Eigen::Vector2d& pos,
                                  const std::vector<physics::Ball>& balls,
                                  const TableContext& table);

/// The cue ball in hand at `pos`: as checkBallPlacement, and behind the head string (centre
/// x < head string x) when `in_hand` is BehindHeadString, in the D when InTheD (a table without
/// snooker marks has no D: refused); refused when `in_hand` is None.
PlacementCheck checkCueBallPlacement(BallInHand in_hand, const Eigen::Vector2d& pos,
                                     const std::vector<physics::Ball>& balls,
                                     const TableContext& table);

/// checkCueBallPlacement as a Result: the position, or the reason it is refused.
Result<Eigen::Vector2d> placeCueBall(BallInHand in_hand, const Eigen::Vector2d& pos,
                                     const std::vector<physics::Ball>& balls,
                                     const TableContext& table);

}  // namespace pool::rules
