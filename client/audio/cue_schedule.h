// When each cue of the current shot starts: once, at its time, none lost, none replayed late.
#pragma once

#include <cstdint>
#include <vector>

#include "client/audio/sound_cue.h"

namespace pool::audio {

/// A cue due now, and how far into the coming audio it starts (keeps the spacing of cues that
/// fell between two updates).
struct DueCue {
  SoundCue cue;
  double delay = 0.0;  ///< s after the start of the next mixed audio
};

struct ScheduleOptions {
  /// s: on the first update of a shot, cues older than this are history, not news (a spectator
  /// joining mid-shot hears what happens from then on, not everything before at once).
  double late_window = 0.1;
  /// s: cues that fell between two updates keep their spacing, squeezed into this much audio.
  double max_spread = 0.05;
};

/// The cue list of one shot and the playback time reached in it. Pure: time is an argument.
class CueSchedule {
 public:
  explicit CueSchedule(const ScheduleOptions& options = {});

  /// A new shot's cues (sorted by time, as cuesFromEvents gives them): the previous shot's
  /// remaining cues are dropped. A shot with the key of the current one (≠ 0) is ignored, so
  /// that a report delivered twice does not sound twice.
  void setShot(std::vector<SoundCue> cues, std::uint64_t key = 0);

  /// More cues of the current shot, learnt as it plays (from frames): each starts at the next
  /// advance() that reaches it, even when its time has passed already.
  void addCues(const std::vector<SoundCue>& cues);

  /// Appends to `due` the cues whose time playback `t` (s since the strike) has reached and that
  /// have not started yet. Time going backwards starts nothing.
  void advance(double t, std::vector<DueCue>& due);

  /// Cues of the current shot not yet started nor skipped.
  std::size_t pending() const { return cues_.size() - next_; }
  /// Cues skipped because the shot was joined late.
  std::size_t skipped() const { return skipped_; }
  /// The key of the current shot (0: none given).
  std::uint64_t key() const { return key_; }

 private:
  ScheduleOptions options_;
  std::vector<SoundCue> cues_;
  std::uint64_t key_ = 0;
  std::size_t next_ = 0;
  std::size_t skipped_ = 0;
  bool joined_ = false;  ///< the shot has had its first update
  double last_ = 0.0;    ///< playback time of the last update
};

}  // namespace pool::audio
