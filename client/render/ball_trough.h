// Where pocketed balls are seen: an open channel along the table's near (-y) side under the rail,
// holding the balls in the order they were pocketed, the first at the foot end.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "client/render/mesh.h"
#include "client/render/scene.h"

namespace pool::render {

/// The slots a trough needs for `set`: one for each of its balls, the cue ball included (a pool
/// set's 16 at least: a carom table keeps the pool table's channel).
int troughSlotsFor(BallSet set);

/// The channel's layout and its fill. Pure (no GL).
class BallTrough {
 public:
  /// A channel of `slots` balls (a pool set's 16 unless told).
  BallTrough(const pool::table::TableGeometry& geometry, double ball_radius, int slots = 16);

  /// Follows a new set of balls: newly pocketed ones join the end of the row (several at once:
  /// by id), balls back on the table leave it.
  void update(const std::vector<SceneBall>& balls);
  /// Centre of the ball in slot `index` (0: at the foot end), table frame, m.
  Eigen::Vector3d slot(int index) const;
  /// The slot of ball `id`, if it is in the trough.
  std::optional<int> slotOf(int id) const;
  /// The channel: floor, front lip and end caps.
  MeshData mesh() const;
  /// How many balls it holds.
  int slots() const { return slots_; }

 private:
  double radius_;
  int slots_;
  Eigen::Vector3d first_;  ///< centre of slot 0
  std::vector<int> order_;
};

}  // namespace pool::render
