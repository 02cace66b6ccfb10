// Builds the scenes the screenshot mode can draw.
#include "client/render/scene.h"

#include "table/rack.h"
#include "table/table_spec.h"

namespace pool::render {

Result<Scene> rackScene(const std::string& table) {
  using namespace pool::table;
  auto spec = loadTableSpec(table);
  if (!spec) return Result<Scene>::fail(spec.error());
  auto geometry = loadTableGeometry(*spec);
  if (!geometry) return Result<Scene>::fail(geometry.error());
  Scene scene;
  scene.geometry = std::move(*geometry);
  scene.ball_radius = spec->params.ball_radius;
  const double r = scene.ball_radius;
  const Eigen::Vector2d head = spotsFor(*spec).head_spot;
  scene.balls.push_back({0, Eigen::Vector3d(head.x(), head.y(), r)});
  for (const BallPlacement& b : rackBalls(RackType::EightBall, *spec, r, 0)) {
    scene.balls.push_back({b.id, Eigen::Vector3d(b.pos.x(), b.pos.y(), r)});
  }
  return Result<Scene>::ok(std::move(scene));
}

}  // namespace pool::render
