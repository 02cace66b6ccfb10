// Builds the scenes the screenshot mode can draw.
#include "client/render/scene.h"

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
  const Eigen::Vector2d head = table.context.spots.head_spot;
  const Eigen::Quaterniond facing = numberTowardViewer();
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

}  // namespace pool::render
