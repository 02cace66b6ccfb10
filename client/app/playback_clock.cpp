// Playback time from arrival times: a slewed offset, a fixed delay, monotonic.
#include "client/app/playback_clock.h"

#include <algorithm>

namespace pool::app {

PlaybackClock::PlaybackClock(PlaybackConfig config) : config_(config), buffer_(config.capacity) {}

void PlaybackClock::clear() {
  buffer_.clear();
  started_ = false;
  play_ = 0.0;
}

std::optional<std::uint32_t> PlaybackClock::shot() const {
  if (const auto* latest = buffer_.latest()) return latest->shot_number;
  return std::nullopt;
}

void PlaybackClock::push(client::TableFrame frame, double now) {
  const double arrival_offset = now - frame.sim_time;
  const bool new_shot = !buffer_.latest() || frame.shot_number > buffer_.latest()->shot_number;
  if (!buffer_.push(std::move(frame))) return;
  if (new_shot || !started_) {
    target_offset_ = offset_ = arrival_offset;
    play_ = now - offset_ - config_.delay;
    last_now_ = now;
    started_ = true;
    return;
  }
  // The earliest arrival relative to its simulated time is the least delayed by the network.
  target_offset_ = std::min(target_offset_, arrival_offset);
}

std::optional<std::vector<physics::Ball>> PlaybackClock::sample(double now) {
  if (!started_) return std::nullopt;
  const double dt = std::max(0.0, now - last_now_);
  last_now_ = now;
  // Slew the offset toward its target at a bounded rate, or jump when far behind.
  const double gap = target_offset_ - offset_;
  const double step = config_.max_skew * dt;
  offset_ =
      std::abs(gap) > config_.resync ? target_offset_ : offset_ + std::clamp(gap, -step, step);
  play_ = std::max(play_, now - offset_ - config_.delay);
  return buffer_.sample(play_);
}

bool PlaybackClock::caughtUp() const {
  const auto* latest = buffer_.latest();
  return latest && play_ >= latest->sim_time;
}

bool PlaybackClock::inMotion(std::uint32_t settled_shots) const {
  const auto playing = shot();
  return playing && (!caughtUp() || settled_shots < *playing);
}

}  // namespace pool::app
