// Which writers matched with a reader have lost their liveliness (their lease ran out, as when
// their process stopped) and not regained it: a DDS listener records each change as it happens.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace pool::net {

/// Follows the liveliness of the writers matched with one reader. The reader's liveliness
/// status tells only the last writer that changed, so a listener takes each change as it comes.
/// The reader must outlive the watch (declare the watch after it).
class LivelinessWatch {
 public:
  /// Starts following `reader` (a dds_entity_t).
  explicit LivelinessWatch(std::int32_t reader);
  /// Stops the listener, waiting for a call in progress.
  ~LivelinessWatch();
  LivelinessWatch(const LivelinessWatch&) = delete;
  LivelinessWatch& operator=(const LivelinessWatch&) = delete;

  /// The publication handles of the writers not alive now, ascending.
  std::vector<std::uint64_t> notAlive() const;
  /// How many changes were seen so far (a new value: notAlive() may differ).
  std::uint64_t changes() const;

  struct State;  ///< what the listener records (liveliness_watch.cpp)

 private:
  std::int32_t reader_;
  std::unique_ptr<State> state_;
};

}  // namespace pool::net
