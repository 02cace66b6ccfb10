// When each frame of a simulated shot is due: paced to simulated time, or all at once.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace pool::server {

/// A run of frames to publish now: indices [first, end).
struct FrameRange {
  std::size_t first = 0;
  std::size_t end = 0;

  std::size_t size() const { return end - first; }
  bool empty() const { return end == first; }
};

/// Hands out the frames of one shot as the clock reaches them. Frame k (simulated time t_k after
/// the strike) is due at start + t_k; unpaced, every frame is due at start. Time is an argument
/// (seconds on any monotonic clock), never read here.
class FramePacer {
 public:
  /// `times`: each frame's simulated time, s, non-decreasing. `start`: when the shot began, s.
  FramePacer(std::vector<double> times, double start, bool unpaced);

  /// The frames due by `now` (s) that were not handed out yet; they count as handed out after.
  FrameRange take(double now);

  /// When the next frame not yet handed out is due (s); empty once all were handed out.
  std::optional<double> nextDue() const;
  /// The server was not running for `seconds`: the frames still to come are due that much later
  /// (they are not sent in one burst).
  void delay(double seconds) { start_ += seconds; }

  /// True once every frame was handed out.
  bool done() const { return next_ == times_.size(); }

  std::size_t count() const { return times_.size(); }

 private:
  double dueAt(std::size_t k) const;

  std::vector<double> times_;
  double start_;
  bool unpaced_;
  std::size_t next_ = 0;
};

}  // namespace pool::server
