// LivelinessWatch: a liveliness-changed listener on a reader, feeding a set guarded by a mutex.
#include "net/liveliness_watch.h"

#include <dds/dds.h>
#include <algorithm>
#include <mutex>
#include <set>

#include "net/dds_detail.h"

namespace pool::net {

struct LivelinessWatch::State {
  mutable std::mutex mutex;
  std::set<std::uint64_t> not_alive;
  std::uint64_t changes = 0;
};

namespace {

/// Called by DDS on its own thread for each change; the status's counts are for that change.
void onLiveliness(dds_entity_t, const dds_liveliness_changed_status_t status, void* arg) {
  auto& state = *static_cast<LivelinessWatch::State*>(arg);
  const std::lock_guard lock(state.mutex);
  if (status.not_alive_count_change > 0) {
    state.not_alive.insert(status.last_publication_handle);
  } else {
    // Alive again, or gone for good (unmatched: not followed here any more).
    state.not_alive.erase(status.last_publication_handle);
  }
  ++state.changes;
}

}  // namespace

LivelinessWatch::LivelinessWatch(std::int32_t reader)
    : reader_(reader), state_(std::make_unique<State>()) {
  dds_listener_t* listener = dds_create_listener(state_.get());
  dds_lset_liveliness_changed(listener, onLiveliness);
  const dds_return_t rc = dds_set_listener(reader_, listener);
  dds_delete_listener(listener);  // the reader keeps a copy
  detail::check(rc, "liveliness listener");
}

LivelinessWatch::~LivelinessWatch() {
  (void)dds_set_listener(reader_, nullptr);
}

std::vector<std::uint64_t> LivelinessWatch::notAlive() const {
  const std::lock_guard lock(state_->mutex);
  return {state_->not_alive.begin(), state_->not_alive.end()};
}

std::uint64_t LivelinessWatch::changes() const {
  const std::lock_guard lock(state_->mutex);
  return state_->changes;
}

}  // namespace pool::net
