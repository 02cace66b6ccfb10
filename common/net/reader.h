// A typed DDS data reader with a named QoS profile: samples come out as owned std::vectors.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "net/dds_detail.h"
#include "net/entity.h"
#include "net/participant.h"
#include "net/partition.h"
#include "net/qos_profiles.h"
#include "net/sample.h"
#include "net/topic.h"

namespace pool::net {

/// Receives samples of T. Throws DdsError at construction, and from take/read only when the
/// reader itself is unusable (a programming error); what peers send never throws.
template <class T>
class Reader {
 public:
  Reader(const Participant& participant, const Topic<T>& topic, const QosProfile& qos)
      : entity_(detail::createReader(participant.handle(), topic.handle(), qos)) {}
  /// A reader in `subscriber`'s partitions.
  Reader(const Subscriber& subscriber, const Topic<T>& topic, const QosProfile& qos)
      : entity_(detail::createReader(subscriber.handle(), topic.handle(), qos)) {}

  /// Removes and returns up to `max` samples that carry data, oldest first per instance.
  /// Instance-state notices (disposals, lost writers) are removed and dropped.
  std::vector<Sample<T>> take(std::size_t max = 256) const { return fetch(true, true, max); }

  /// Like take, but the samples stay in the reader (marked read) and come back on the next read:
  /// with keep-last 1, the latest sample of each instance. At most `max` in one call.
  std::vector<Sample<T>> read(std::size_t max = 64) const { return fetch(false, true, max); }

  /// Removes and returns up to `max` samples including instance-state notices; check
  /// `meta().valid` (a notice has only its @key fields set) and `meta().instance`.
  std::vector<Sample<T>> takeWithNotices(std::size_t max = 256) const {
    return fetch(true, false, max);
  }

  /// Removes up to `max` samples and calls `each(const T&, const SampleMeta&)` on those with data,
  /// without copying them (the memory is DDS's until `each` returns). Returns the count taken.
  template <class F>
  std::size_t takeEach(F&& each, std::size_t max = 256) const {
    return detail::fetchLoaned(handle(), true, max, [&](const void* s, const SampleMeta& m) {
      if (m.valid) {
        each(*static_cast<const T*>(s), m);
      }
    });
  }

  /// The participant (its GUID in hex) of a matched writer, from a sample's
  /// `meta().publication_handle`; empty when that writer is no longer matched.
  std::string participantOf(std::uint64_t publication) const {
    return detail::participantOf(handle(), publication);
  }

  /// Writers matched with this reader.
  MatchedStatus subscriptionMatched() const { return detail::subscriptionMatched(handle()); }

  /// The publication handles (as `meta().publication_handle`) of the writers matched now, in
  /// ascending order.
  std::vector<std::uint64_t> matchedWriters() const {
    return detail::matchedPublications(handle());
  }

  /// The liveliness of matched writers; reading it resets the change counts.
  LivelinessStatus livelinessChanged() const { return detail::livelinessChanged(handle()); }

  /// Blocks until at least `count` writers match or `timeout` passes; true when they did.
  bool waitForWriters(std::uint32_t count, std::chrono::nanoseconds timeout) const {
    return detail::waitForMatches(handle(), false, count, timeout);
  }

  std::int32_t handle() const { return entity_.handle(); }

 private:
  static constexpr std::size_t kBatch = 16;

  std::vector<Sample<T>> fetch(bool take, bool only_valid, std::size_t max) const {
    std::vector<Sample<T>> out;
    while (out.size() < max) {
      // A read leaves samples in place, so it gets them in one call; a take goes in batches.
      const std::size_t want = take ? std::min(kBatch, max - out.size()) : max;
      if (fetchBatch(take, only_valid, want, out) < want || !take) {
        break;
      }
    }
    return out;
  }

  std::size_t fetchBatch(bool take, bool only_valid, std::size_t n,
                         std::vector<Sample<T>>& out) const {
    // Fresh zeroed samples that DDS fills, allocating their sequences (freed with each Sample).
    std::vector<Sample<T>> batch(n);
    std::vector<void*> pointers(n);
    std::vector<SampleMeta> metas(n);
    for (std::size_t i = 0; i < n; ++i) {
      pointers[i] = batch[i].get();
    }
    const std::size_t got = detail::fetchInto(handle(), take, pointers.data(), metas.data(), n);
    for (std::size_t i = 0; i < got; ++i) {
      batch[i].meta() = metas[i];
      if (metas[i].valid || !only_valid) {
        out.push_back(std::move(batch[i]));
      }
    }
    return got;
  }

  Entity entity_;
};

}  // namespace pool::net
