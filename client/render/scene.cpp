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

Result<Scene> tableScene(const std::string& table) {
  auto spec = pool::table::loadTableSpec(table);
  if (!spec) return Result<Scene>::fail(spec.error());
  auto geometry = pool::table::loadTableGeometry(*spec);
  if (!geometry) return Result<Scene>::fail(geometry.error());
  Scene scene;
  scene.geometry = std::move(*geometry);
  scene.ball_radius = spec->params.ball_radius;
  scene.cushion_width = spec->cushion_width;
  return Result<Scene>::ok(std::move(scene));
}

Result<Scene> rackScene(const std::string& table) {
  using namespace pool::table;
  auto spec = loadTableSpec(table);
  if (!spec) return Result<Scene>::fail(spec.error());
  auto empty = tableScene(table);
  if (!empty) return empty;
  Scene scene = std::move(*empty);
  const double r = scene.ball_radius;
  const Eigen::Vector2d head = spotsFor(*spec).head_spot;
  const Eigen::Quaterniond facing = numberTowardViewer();
  scene.balls.push_back({0, Eigen::Vector3d(head.x(), head.y(), r), facing});
  for (const BallPlacement& b : rackBalls(RackType::EightBall, *spec, r, 0)) {
    scene.balls.push_back({b.id, Eigen::Vector3d(b.pos.x(), b.pos.y(), r), facing});
  }
  return Result<Scene>::ok(std::move(scene));
}

}  // namespace pool::render
