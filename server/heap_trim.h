// Gives the heap that a flood (joins, commands, aims) freed back to the system once it is over.
#pragma once

#include <cstdint>

namespace pool::server {

/// Decides when to hand freed heap back: once at least `kFloodEvents` events (joins, refused
/// commands, dropped aims) have been
/// counted since the last time and none for `kQuiet` s (a flood is over). The memory a flood
/// used (DDS receive buffers and instances, replies, tallies) is freed when its clients are
/// gone, but glibc keeps freed memory in its arenas; returning it puts the resident size back
/// near its baseline. Pure logic: time and counts are passed in.
class HeapTrim {
 public:
  static constexpr std::uint64_t kFloodEvents = 1000;
  static constexpr double kQuiet = 2.0;

  /// `events`: every such event counted so far; true when it is time to
  /// trim (then the next flood is counted from here).
  bool due(std::uint64_t events, double now);

 private:
  std::uint64_t trimmed_at_ = 0;  ///< events counted at the last trim
  std::uint64_t seen_ = 0;        ///< events counted at the last call
  double changed_at_ = 0.0;       ///< when the count last changed
};

/// Returns free heap memory to the system (glibc's malloc_trim); the resident size drops by what
/// was free. Returns the bytes of resident memory given back, as far as the process can tell.
long releaseFreeHeap();

/// Bytes of heap in use (allocated and not freed) in the main arena and the others (glibc's
/// mallinfo2): what a flood left allocated, as against what is merely resident.
long heapInUse();

}  // namespace pool::server
