// Blocking until data, a status change or a wake-up arrives, with a timeout.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "net/entity.h"
#include "net/participant.h"
#include "net/reader.h"

namespace pool::net {

/// A condition another thread (or a signal handler's flag watcher) sets to wake a WaitSet.
class GuardCondition {
 public:
  /// Throws DdsError when DDS refuses it.
  explicit GuardCondition(const Participant& participant);

  /// Wakes every WaitSet this is attached to until reset().
  void trigger() const;
  void reset() const;

  std::int32_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

/// Waits for any of the attached conditions, each known by a caller-chosen tag.
class WaitSet {
 public:
  /// Throws DdsError when DDS refuses it.
  explicit WaitSet(const Participant& participant);

  /// Wakes while `reader` holds samples not yet taken or read (data or instance-state notices).
  template <class T>
  void attachData(const Reader<T>& reader, std::int64_t tag) {
    attachUnreadCondition(reader.handle(), tag);
  }

  /// Stops waking for `reader`'s data (before the reader is deleted, or to stop watching it).
  template <class T>
  void detachData(const Reader<T>& reader) {
    detachUnreadCondition(reader.handle());
  }

  /// Wakes when the liveliness of a writer matched with `reader` changes (until the reader's
  /// livelinessChanged() is queried).
  template <class T>
  void attachLiveliness(const Reader<T>& reader, std::int64_t tag) {
    attachLivelinessStatus(reader.handle(), tag);
  }

  /// Wakes while `guard` is triggered.
  void attach(const GuardCondition& guard, std::int64_t tag);

  /// Blocks until some condition holds or `timeout` passes. Returns the tags of the conditions
  /// that hold (empty on timeout).
  std::vector<std::int64_t> wait(std::chrono::nanoseconds timeout) const;

 private:
  void attachUnreadCondition(std::int32_t reader, std::int64_t tag);
  void detachUnreadCondition(std::int32_t reader);
  void attachLivelinessStatus(std::int32_t reader, std::int64_t tag);

  Entity entity_;
  struct ReadCondition {
    std::int32_t reader;
    Entity condition;  ///< a child of `reader`
  };
  std::vector<ReadCondition> conditions_;  // read conditions created here
  std::size_t attached_ = 0;
};

}  // namespace pool::net
