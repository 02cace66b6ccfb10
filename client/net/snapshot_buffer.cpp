// Frame buffering and interpolation.
#include "client/net/snapshot_buffer.h"

#include <algorithm>

namespace pool::client {
namespace {

std::vector<physics::Ball> blend(const TableFrame& a, const TableFrame& b, double t) {
  const double span = b.sim_time - a.sim_time;
  const double u = span > 0 ? std::clamp((t - a.sim_time) / span, 0.0, 1.0) : 1.0;
  std::vector<physics::Ball> out = a.balls;
  for (auto& ball : out) {
    const auto it = std::find_if(b.balls.begin(), b.balls.end(),
                                 [&](const physics::Ball& o) { return o.id == ball.id; });
    if (it == b.balls.end()) continue;
    ball.pos = (1 - u) * ball.pos + u * it->pos;
    ball.vel = (1 - u) * ball.vel + u * it->vel;
    // A rolling ball must turn smoothly too, not in steps at each snapshot.
    ball.orient = ball.orient.slerp(u, it->orient);
  }
  return out;
}

}  // namespace

bool SnapshotBuffer::push(TableFrame frame) {
  if (!frames_.empty()) {
    const TableFrame& newest = frames_.back();
    if (frame.shot_number > newest.shot_number) {
      frames_.clear();
    } else if (frame.shot_number < newest.shot_number || frame.frame <= newest.frame) {
      return false;
    }
  }
  frames_.push_back(std::move(frame));
  while (frames_.size() > capacity_) frames_.pop_front();
  return true;
}

std::optional<std::vector<physics::Ball>> SnapshotBuffer::sample(double sim_time) const {
  if (frames_.empty()) return std::nullopt;
  if (sim_time <= frames_.front().sim_time) return frames_.front().balls;
  for (std::size_t i = 1; i < frames_.size(); ++i) {
    if (sim_time <= frames_[i].sim_time) return blend(frames_[i - 1], frames_[i], sim_time);
  }
  return frames_.back().balls;
}

}  // namespace pool::client
