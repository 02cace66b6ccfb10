// Smooth motion: plays a shot's frames back on the caller's clock a little behind their arrival,
// interpolated between snapshots, never stepping back in time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "client/net/match_types.h"
#include "client/net/snapshot_buffer.h"

namespace pool::app {

/// How the playback follows the stream.
struct PlaybackConfig {
  double delay = 0.1;         ///< s behind the earliest-arriving frame (covers a lost snapshot)
  double max_skew = 0.05;     ///< fraction the playback rate may differ from 1 while catching up
  double resync = 0.5;        ///< s: a lag beyond this is jumped over at once
  std::size_t capacity = 32;  ///< frames kept
};

/// One match's shot in motion, as drawn. Time (`now`, s) is the caller's, on any steady clock.
class PlaybackClock {
 public:
  explicit PlaybackClock(PlaybackConfig config = {});

  /// A frame received at `now`. A frame of a newer shot starts that shot's playback.
  void push(client::TableFrame frame, double now);
  /// The balls to draw at `now`: interpolated at the playback time, which only moves forward.
  /// Empty before the first frame.
  std::optional<std::vector<physics::Ball>> sample(double now);

  /// The simulated time (s since the strike) last drawn.
  double playTime() const { return play_; }
  /// True once the playback has reached the newest frame received.
  bool caughtUp() const;
  /// True while the shot being played is still to be drawn: the playback has not reached its
  /// newest frame, or the match's state counts only `settled_shots` shots, fewer than its number
  /// (frames and states travel on different topics and may arrive in either order).
  bool inMotion(std::uint32_t settled_shots) const;
  /// The shot being played, if any frame arrived.
  std::optional<std::uint32_t> shot() const;
  void clear();

 private:
  PlaybackConfig config_;
  client::SnapshotBuffer buffer_;
  double target_offset_ = 0.0;  ///< smallest (arrival − sim time) seen this shot, s
  double offset_ = 0.0;         ///< the offset in use, slewed toward target_offset_
  double play_ = 0.0;
  double last_now_ = 0.0;
  bool started_ = false;
};

}  // namespace pool::app
