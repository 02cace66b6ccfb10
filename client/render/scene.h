// What the renderer draws: a table's geometry and the balls on it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/result.h"
#include "table/table_geometry.h"

namespace pool::render {

/// One ball on the table (table frame, metres; the centre is at z = radius).
struct SceneBall {
  int id = 0;  ///< 0: cue ball
  Eigen::Vector2d pos;
};

/// A table and its balls.
struct Scene {
  pool::table::TableGeometry geometry;
  double ball_radius = 0.0;
  std::vector<SceneBall> balls;
};

/// A freshly racked 8-ball table (rack seed 0) with the cue ball on the head spot.
Result<Scene> rackScene(const std::string& table = "wpa-9ft");

}  // namespace pool::render
