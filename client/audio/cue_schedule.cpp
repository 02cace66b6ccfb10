// Starts each cue once when playback reaches it; a late first update skips the history.
#include "client/audio/cue_schedule.h"

#include <algorithm>
#include <cmath>

namespace pool::audio {

CueSchedule::CueSchedule(const ScheduleOptions& options) : options_(options) {}

void CueSchedule::setShot(std::vector<SoundCue> cues, std::uint64_t key) {
  if (key != 0 && key == key_) return;
  cues_ = std::move(cues);
  key_ = key;
  next_ = 0;
  skipped_ = 0;
  joined_ = false;
  last_ = 0.0;
}

void CueSchedule::addCues(const std::vector<SoundCue>& cues) {
  for (const SoundCue& c : cues) {
    // Among the cues still to come, in time order; never behind one already started.
    const auto at = std::upper_bound(cues_.begin() + static_cast<long>(next_), cues_.end(), c.t,
                                     [](double t, const SoundCue& x) { return t < x.t; });
    cues_.insert(at, c);
  }
}

void CueSchedule::advance(double t, std::vector<DueCue>& due) {
  if (!std::isfinite(t)) return;
  if (!joined_) {
    // Joining: what happened before the late window is history.
    joined_ = true;
    while (next_ < cues_.size() && cues_[next_].t < t - options_.late_window) {
      ++next_;
      ++skipped_;
    }
    last_ = next_ < cues_.size() ? std::min(t, cues_[next_].t) : t;
  } else if (t <= last_) {
    return;
  }
  // The cues keep their spacing in the coming audio; a long gap (skipped frames) is squeezed
  // into max_spread so that they are not later still.
  const double gap = t - last_;
  const double squeeze = gap > options_.max_spread ? options_.max_spread / gap : 1.0;
  for (; next_ < cues_.size() && cues_[next_].t <= t; ++next_) {
    const double delay = std::max(0.0, (cues_[next_].t - last_) * squeeze);
    due.push_back({cues_[next_], delay});
  }
  last_ = t;
}

}  // namespace pool::audio
