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
  scene.balls.push_back({0, spotsFor(*spec).head_spot});
  for (const BallPlacement& b : rackBalls(RackType::EightBall, *spec, scene.ball_radius, 0)) {
    scene.balls.push_back({b.id, b.pos});
  }
  return Result<Scene>::ok(std::move(scene));
}

}  // namespace pool::render
