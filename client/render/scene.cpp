// Builds the scenes the screenshot mode can draw.
#include "client/render/scene.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "table/rack.h"
#include "table/table_spec.h"

namespace pool::render {

Eigen::Quaterniond numberTowardViewer() {
  const Eigen::Vector3d toward = Eigen::Vector3d(0.0, -0.55, 1.0).normalized();
  const Eigen::Vector3d along = Eigen::Vector3d::UnitX();
  Eigen::Matrix3d r;
  r.col(0) = toward;
  r.col(1) = along.cross(toward);
  r.col(2) = along;
  return Eigen::Quaterniond(r);
}

Scene tableScene(const game::LoadedTable& table) {
  Scene scene;
  scene.geometry = table.geometry;
  scene.ball_radius = table.spec.params.ball_radius;
  scene.cushion_width = table.spec.cushion_width;
  scene.ball_set = ballSetOf(table.spec);
  scene.snooker_marks = table::snookerSpotsFor(table.spec);
  return scene;
}

Result<Scene> tableScene(const std::string& table) {
  auto loaded = game::loadTable(table);
  if (!loaded) return Result<Scene>::fail(loaded.error());
  return Result<Scene>::ok(tableScene(*loaded));
}

Scene rackScene(const game::LoadedTable& table) {
  Scene scene = tableScene(table);
  const double r = scene.ball_radius;
  const Eigen::Quaterniond facing = numberTowardViewer();
  if (scene.snooker_marks) {
    // A frame's opening (table::snookerRack), the cue ball first, in the D.
    for (const table::BallPlacement& b : table::snookerRack(table.spec, r)) {
      scene.balls.push_back({b.id, Eigen::Vector3d(b.pos.x(), b.pos.y(), r), facing});
    }
    return scene;
  }
  const Eigen::Vector2d head = table.context.spots.head_spot;
  scene.balls.push_back({0, Eigen::Vector3d(head.x(), head.y(), r), facing});
  for (const table::BallPlacement& b :
       table::rackBalls(table::RackType::EightBall, table.spec, r, 0)) {
    scene.balls.push_back({b.id, Eigen::Vector3d(b.pos.x(), b.pos.y(), r), facing});
  }
  return scene;
}

Result<Scene> rackScene(const std::string& table) {
  auto loaded = game::loadTable(table);
  if (!loaded) return Result<Scene>::fail(loaded.error());
  return Result<Scene>::ok(rackScene(*loaded));
}

Result<Scene> withBalls(Scene scene, const table::TableSpec& spec,
                        const std::vector<double>& cue_at, const std::vector<double>& balls) {
  const double r = scene.ball_radius;
  // Within a micrometre: a ball frozen to a cushion, given to six decimals, may round past it.
  const auto on_slate = [&](double x, double y) {
    return std::abs(x) <= spec.length / 2 - r + 1e-6 && std::abs(y) <= spec.width / 2 - r + 1e-6;
  };
  if (!cue_at.empty()) {
    if (cue_at.size() != 2 || scene.balls.empty() || !on_slate(cue_at[0], cue_at[1])) {
      return Result<Scene>::fail("--cue-at needs X Y on the slate");
    }
    scene.balls.front().pos.head<2>() = Eigen::Vector2d(cue_at[0], cue_at[1]);
  }
  if (balls.empty()) return Result<Scene>::ok(std::move(scene));
  if (balls.size() % 3 != 0) return Result<Scene>::fail("--balls needs ID X Y for each ball");
  const int most = maxBallIdOf(scene.ball_set);
  scene.balls.resize(std::min<std::size_t>(scene.balls.size(), 1));  // the cue ball stays
  for (std::size_t i = 0; i < balls.size(); i += 3) {
    const double id = balls[i], x = balls[i + 1], y = balls[i + 2];
    if (id != std::floor(id) || id < 1 || id > most || !on_slate(x, y)) {
      std::ostringstream out;
      out << "--balls: ball " << id << " at " << x << ", " << y << " is not a ball 1-" << most
          << " on the slate";
      return Result<Scene>::fail(out.str());
    }
    scene.balls.push_back(
        {static_cast<int>(id), Eigen::Vector3d(x, y, r), numberTowardViewer(), false});
  }
  return Result<Scene>::ok(std::move(scene));
}

}  // namespace pool::render
