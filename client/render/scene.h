// What the renderer draws: a table's geometry and the balls on it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "client/render/palette.h"
#include "core/result.h"
#include "game/loaded_table.h"
#include "table/snooker_spots.h"
#include "table/table_geometry.h"

namespace pool::render {

/// One ball (table frame, metres): on the slate its centre is at z = radius; pocketed balls lie
/// lower, in the trough under the table.
struct SceneBall {
  int id = 0;  ///< 0: cue ball
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body → table frame
  bool pocketed = false;
};

/// A table and its balls.
struct Scene {
  pool::table::TableGeometry geometry;
  double ball_radius = 0.0;
  double cushion_width = 0.05;       ///< nose to the back of the cushion (the spec's), m
  BallSet ball_set = BallSet::Pool;  ///< how the balls look (a carom table's: white, yellow, red)
  /// A snooker table's baulk line, D and spots, chalked on the felt; none on other tables.
  std::optional<pool::table::SnookerSpots> snooker_marks;
  std::vector<SceneBall> balls;
};

/// An orientation that shows a ball's number (body +x) to the overview camera (up and toward
/// -y), its band axis (body z) along the table.
Eigen::Quaterniond numberTowardViewer();

/// The loaded table `table` with no balls.
Scene tableScene(const game::LoadedTable& table);
/// The table named `table` (a spec name, e.g. "wpa-9ft"), loaded through the game kit, with no
/// balls.
Result<Scene> tableScene(const std::string& table);

/// A freshly racked 8-ball table (rack seed 0) with the cue ball on the head spot, every ball
/// turned to show its number to the overview camera. A snooker table gets a snooker frame's
/// opening instead: the colours on their spots, the fifteen reds packed in a triangle behind the
/// pink (its apex a millimetre clear of the pink), the cue ball in the D.
Scene rackScene(const game::LoadedTable& table);
/// As above, of the table named `table`.
Result<Scene> rackScene(const std::string& table = "wpa-9ft");

/// Puts the cue ball (the scene's first ball) at `cue_at` (x, y, m; empty: where it is) and,
/// when `balls` holds an ID X Y triple for each object ball, those balls in place of the scene's
/// others. Fails, saying why, on a list that is not triples, an id not of the scene's ball set
/// (1 to maxBallIdOf) or a ball off the playing surface of `spec`.
Result<Scene> withBalls(Scene scene, const pool::table::TableSpec& spec,
                        const std::vector<double>& cue_at, const std::vector<double>& balls);

}  // namespace pool::render
