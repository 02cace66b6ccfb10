// A typed DDS data writer with a named QoS profile.
#pragma once

#include <string>

#include <chrono>
#include <cstdint>

#include "net/dds_detail.h"
#include "net/entity.h"
#include "net/participant.h"
#include "net/partition.h"
#include "net/qos_profiles.h"
#include "net/topic.h"

namespace pool::net {

/// Publishes samples of T. Throws DdsError at construction only; later failures are a Status.
template <class T>
class Writer {
 public:
  Writer(const Participant& participant, const Topic<T>& topic, const QosProfile& qos)
      : entity_(detail::createWriter(participant.handle(), topic.handle(), qos)) {}
  /// A writer in `publisher`'s partitions.
  Writer(const Publisher& publisher, const Topic<T>& topic, const QosProfile& qos)
      : entity_(detail::createWriter(publisher.handle(), topic.handle(), qos)) {}

  /// Publishes `sample` (its instance is the value of its @key fields). A reliable write may block
  /// up to the profile's max_blocking when readers lag, then fails with a timeout.
  Status write(const T& sample) const { return detail::write(handle(), &sample); }

  /// Tells readers the instance of `key` (only its @key fields are read) no longer exists.
  Status dispose(const T& key) const { return detail::dispose(handle(), &key); }

  /// Writes `sample`; empty when written, else why not (for callers that report, not branch).
  std::string writeOrWhy(const T& sample) const {
    auto status = write(sample);
    return status ? std::string() : status.error;
  }

  /// Stops writing the instance of `key` without disposing it.
  Status unregister(const T& key) const { return detail::unregister(handle(), &key); }

  /// Readers matched with this writer.
  MatchedStatus publicationMatched() const { return detail::publicationMatched(handle()); }

  /// Blocks until at least `count` readers match or `timeout` passes; true when they did.
  bool waitForReaders(std::uint32_t count, std::chrono::nanoseconds timeout) const {
    return detail::waitForMatches(handle(), true, count, timeout);
  }

  std::int32_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

}  // namespace pool::net
