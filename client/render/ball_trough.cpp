// The pocketed-ball channel: placed from the table mesh's extent, filled in pocketing order.
#include "client/render/ball_trough.h"

#include <algorithm>
#include <limits>

namespace pool::render {

namespace {

constexpr int kPoolSlots = 16;  // the cue ball and 1-15
constexpr double kGap = 0.004;  ///< between the rail's outer face and a ball, m

}  // namespace

int troughSlotsFor(BallSet set) {
  return std::max(kPoolSlots, maxBallIdOf(set) + 1);
}

BallTrough::BallTrough(const pool::table::TableGeometry& geometry, double ball_radius, int slots)
    : radius_(ball_radius), slots_(slots) {
  // The channel hangs in front of the near rail's outer face, its balls just under the slate.
  double near_y = std::numeric_limits<double>::max();
  for (const auto& part : geometry.parts) {
    for (const auto& v : part.vertices) near_y = std::min(near_y, v.y());
  }
  if (geometry.parts.empty()) near_y = -geometry.width * 0.5;
  const double half_row = slots_ * ball_radius;
  first_ = Eigen::Vector3d(half_row - ball_radius, near_y - ball_radius - kGap, -ball_radius);
}

void BallTrough::update(const std::vector<SceneBall>& balls) {
  std::erase_if(order_, [&](int id) {
    return std::none_of(balls.begin(), balls.end(),
                        [&](const SceneBall& b) { return b.id == id && b.pocketed; });
  });
  std::vector<int> arrived;
  for (const SceneBall& b : balls) {
    if (b.pocketed && !slotOf(b.id)) arrived.push_back(b.id);
  }
  std::sort(arrived.begin(), arrived.end());
  order_.insert(order_.end(), arrived.begin(), arrived.end());
}

Eigen::Vector3d BallTrough::slot(int index) const {
  return first_ - Eigen::Vector3d(2.0 * radius_ * index, 0.0, 0.0);
}

std::optional<int> BallTrough::slotOf(int id) const {
  const auto it = std::find(order_.begin(), order_.end(), id);
  if (it == order_.end()) return std::nullopt;
  return static_cast<int>(it - order_.begin());
}

MeshData BallTrough::mesh() const {
  const auto r = static_cast<float>(radius_);
  const float wall = 0.3f * r;
  const glm::vec3 first(static_cast<float>(first_.x()), static_cast<float>(first_.y()),
                        static_cast<float>(first_.z()));
  const float x_foot = first.x + r + wall;
  const float x_head = first.x - (2.0f * static_cast<float>(slots_) - 1.0f) * r - wall;
  const float y_back = first.y + r + static_cast<float>(kGap);
  const float y_front = first.y - r;
  const float z_floor = first.z - r;
  MeshData mesh = box({x_head, y_front - wall, z_floor - wall}, {x_foot, y_back, z_floor});
  append(mesh, box({x_head, y_front - wall, z_floor}, {x_foot, y_front, first.z - 0.4f * r}));
  append(mesh, box({x_head, y_front, z_floor}, {x_head + wall, y_back, first.z + 0.4f * r}));
  append(mesh, box({x_foot - wall, y_front, z_floor}, {x_foot, y_back, first.z + 0.4f * r}));
  return mesh;
}

}  // namespace pool::render
