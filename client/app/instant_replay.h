// The instant replay: the last shot's frames kept as they arrived, played again at real speed (or
// slower) on the caller's clock, until their end or until the live game moves again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "client/net/match_types.h"
#include "client/net/snapshot_buffer.h"

namespace pool::app {

/// One match's last shot, for replaying. Time (`now`, s) is the caller's, on any steady clock.
class InstantReplay {
 public:
  /// Keeps up to `capacity` frames of a shot (60 Hz: a minute).
  explicit InstantReplay(std::size_t capacity = 3600) : frames_(capacity) {}

  /// A frame received: a frame of a newer shot replaces the kept one (and ends a replay of it).
  void record(const client::TableFrame& frame);
  /// Forgets the kept shot (another match followed).
  void clear();

  /// The shot kept, once it has at least two frames.
  std::optional<std::uint32_t> shot() const;
  /// Starts replaying the kept shot from its strike at `now`, `speed` times real time (0.1–1).
  /// False when no shot is kept.
  bool start(double now, double speed = 1.0);
  void stop() { start_.reset(); }
  bool playing() const { return start_.has_value(); }
  /// The balls of the replay at `now`, interpolated between the kept frames; once the replay has
  /// shown the table at rest for kHold s it stops and this is empty (the live table again).
  std::optional<std::vector<physics::Ball>> sample(double now);
  /// The replay's simulated time at the last sample (s since the strike).
  double replayTime() const { return replay_time_; }

  /// How long the replay holds the table at rest after the shot's last frame, s.
  static constexpr double kHold = 0.5;

 private:
  client::SnapshotBuffer frames_;
  std::optional<double> start_;
  double speed_ = 1.0;
  double replay_time_ = 0.0;
};

}  // namespace pool::app
