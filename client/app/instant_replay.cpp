// Keeping and replaying the last shot's frames.
#include "client/app/instant_replay.h"

#include <algorithm>

namespace pool::app {

void InstantReplay::record(const client::TableFrame& frame) {
  const client::TableFrame* kept = frames_.latest();
  if (kept && frame.shot_number > kept->shot_number) start_.reset();  // the live game moves on
  frames_.push(frame);
}

void InstantReplay::clear() {
  frames_.clear();
  start_.reset();
}

std::optional<std::uint32_t> InstantReplay::shot() const {
  const client::TableFrame* kept = frames_.latest();
  if (!kept || frames_.size() < 2) return std::nullopt;
  return kept->shot_number;
}

bool InstantReplay::start(double now, double speed) {
  if (!shot()) return false;
  speed_ = std::clamp(speed, 0.1, 1.0);
  start_ = now;
  replay_time_ = 0.0;
  return true;
}

std::optional<std::vector<physics::Ball>> InstantReplay::sample(double now) {
  if (!start_) return std::nullopt;
  const client::TableFrame* last = frames_.latest();
  if (!last) {
    start_.reset();
    return std::nullopt;
  }
  replay_time_ = std::max(0.0, now - *start_) * speed_;
  if (replay_time_ > last->sim_time + kHold * speed_) {
    start_.reset();
    return std::nullopt;
  }
  return frames_.sample(replay_time_);
}

}  // namespace pool::app
