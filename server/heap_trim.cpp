// When a flood is over, and glibc's malloc_trim to give its freed memory back.
#include "server/heap_trim.h"

#include <malloc.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace pool::server {

namespace {

/// Resident pages of this process (from /proc/self/statm), in bytes; 0 when unreadable.
long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * ::sysconf(_SC_PAGESIZE);
}

}  // namespace

bool HeapTrim::due(std::uint64_t events, double now) {
  if (events != seen_) {
    seen_ = events;
    changed_at_ = now;
    return false;
  }
  if (events - trimmed_at_ < kFloodEvents || now - changed_at_ < kQuiet) return false;
  trimmed_at_ = events;
  return true;
}

long heapInUse() {
  return static_cast<long>(::mallinfo2().uordblks);
}

long releaseFreeHeap() {
  const long before = residentBytes();
  ::malloc_trim(0);
  return before - residentBytes();
}

}  // namespace pool::server
