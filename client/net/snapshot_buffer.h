// A small buffer of the latest table frames of one match, for smooth display at any snapshot
// rate: positions are interpolated between the two frames around a render time.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "client/net/match_types.h"

namespace pool::client {

/// Frames of the shot in motion, oldest first. Time is the caller's: `received` stamps are
/// seconds on any clock the caller keeps consistent.
class SnapshotBuffer {
 public:
  explicit SnapshotBuffer(std::size_t capacity = 8) : capacity_(capacity) {}

  /// Adds a frame. A frame of a newer shot clears the older shot's frames; a frame older than the
  /// newest of its shot (best-effort delivery may reorder) is dropped. False when dropped.
  bool push(TableFrame frame);

  /// The balls at simulated time `sim_time` (s since the strike of the buffered shot): linear
  /// interpolation of positions and velocities, spherical of orientations, between the frames
  /// around it (motion state from the earlier one), the first or last frame outside their range.
  /// Empty when the buffer is empty.
  std::optional<std::vector<physics::Ball>> sample(double sim_time) const;

  std::size_t size() const { return frames_.size(); }
  const TableFrame* latest() const { return frames_.empty() ? nullptr : &frames_.back(); }
  void clear() { frames_.clear(); }

 private:
  std::size_t capacity_;
  std::deque<TableFrame> frames_;
};

}  // namespace pool::client
