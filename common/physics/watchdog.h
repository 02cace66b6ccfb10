// The watchdog: finds balls in impossible states (non-finite, inside another, off every surface).
#pragma once

#include <string>
#include <vector>

#include "physics/ball.h"
#include "physics/predict.h"
#include "table/physics_params.h"

namespace pool::physics {

/// What to do with one ball in an impossible state.
struct WatchdogFix {
  size_t index = 0;     ///< into the balls checked
  bool remove = false;  ///< true: take it off the table; false: re-spot it at `spot`
  Vec2 spot = Vec2::Zero();
  std::string reason;  ///< "non-finite state", "inside another ball", "left the slate"
};

/// True if a ball's centre at p may rest on the slate: not inside a cushion or jaw (at least the
/// nose's reach from every nose line and jaw point, on the playing side), not over a pocket
/// hole; a pocket's mouth, past the line of the rails, counts.
bool onSlate(const Vec2& p, const TableFeatures& features, const table::PhysicsParams& params);

/// The first point on the long string free of every other ball on the table, from the foot
/// spot toward the foot cushion, then toward the head; false if there is none.
bool freeSpotOnLongString(const std::vector<Ball>& balls, size_t self, const TableFeatures& f,
                          const table::PhysicsParams& p, Vec2& spot);

/// Checks every ball on the table. A ball that is non-finite, overlaps another by more than
/// 1 mm, or is outside the table's outline while not airborne gets a fix: re-spotted on the
/// long string at the first free point from the foot spot, or removed if there is none.
std::vector<WatchdogFix> checkBalls(const std::vector<Ball>& balls, const TableFeatures& features,
                                    const table::PhysicsParams& params);

}  // namespace pool::physics
