// Where pocketed balls are seen: an open channel along the table's near (-y) side under the rail,
// holding the balls in the order they were pocketed, the first at the foot end.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "client/render/mesh.h"
#include "client/render/scene.h"

namespace pool::render {

/// The channel's layout and its fill. Pure (no GL).
class BallTrough {
 public:
  BallTrough(const pool::table::TableGeometry& geometry, double ball_radius);

  /// Follows a new set of balls: newly pocketed ones join the end of the row (several at once:
  /// by id), balls back on the table leave it.
  void update(const std::vector<SceneBall>& balls);
  /// Centre of the ball in slot `index` (0: at the foot end), table frame, m.
  Eigen::Vector3d slot(int index) const;
  /// The slot of ball `id`, if it is in the trough.
  std::optional<int> slotOf(int id) const;
  /// The channel: floor, front lip and end caps.
  MeshData mesh() const;

 private:
  double radius_;
  Eigen::Vector3d first_;  ///< centre of slot 0
  std::vector<int> order_;
};

}  // namespace pool::render
