// Frame pacing: the wall clock catching up with simulated time.
#include "server/match/frame_pacer.h"

namespace pool::server {

FramePacer::FramePacer(std::vector<double> times, double start, bool unpaced)
    : times_(std::move(times)), start_(start), unpaced_(unpaced) {}

double FramePacer::dueAt(std::size_t k) const {
  return unpaced_ ? start_ : start_ + times_[k];
}

FrameRange FramePacer::take(double now) {
  FrameRange range{next_, next_};
  while (range.end < times_.size() && dueAt(range.end) <= now) ++range.end;
  next_ = range.end;
  return range;
}

std::optional<double> FramePacer::nextDue() const {
  if (done()) return std::nullopt;
  return dueAt(next_);
}

}  // namespace pool::server
