// One owned sample of a wire type plus what DDS says about it; frees its sequences when it goes.
#pragma once

#include <cstdint>

#include "net/dds_detail.h"
#include "net/messages.h"

namespace pool::net {

/// The life of the instance a sample belongs to when it was read.
enum class InstanceState : std::uint8_t {
  Alive,      ///< some writer has it registered and not disposed
  Disposed,   ///< a writer disposed it (e.g. a closed match)
  NoWriters,  ///< every writer of it is gone (unregistered or lost liveliness)
};

const char* toString(InstanceState state);

/// What DDS reports with a sample.
struct SampleMeta {
  bool valid = true;  ///< false: no data, only a change of instance state (key fields are set)
  InstanceState instance = InstanceState::Alive;
  std::int64_t source_time_ns = 0;       ///< the writer's timestamp, ns since the Unix epoch
  std::uint64_t instance_handle = 0;     ///< the instance (one per key value) in this reader
  std::uint64_t publication_handle = 0;  ///< the writer it came from, in this participant
};

/// Owns one wire sample T (a generated C struct). Sequences inside it whose `_release` is true are
/// freed with it, whether DDS allocated them (samples taken from a Reader) or resizeSequence did
/// (samples built for a Writer). Starts zeroed. Move-only; a moved-from sample is zeroed.
template <class T>
class Sample {
 public:
  Sample() = default;
  ~Sample() { release(); }
  Sample(const Sample&) = delete;
  Sample& operator=(const Sample&) = delete;
  Sample(Sample&& other) noexcept : value_(other.value_), meta_(other.meta_) { other.value_ = T{}; }
  Sample& operator=(Sample&& other) noexcept {
    if (this != &other) {
      release();
      value_ = other.value_;
      meta_ = other.meta_;
      other.value_ = T{};
    }
    return *this;
  }

  T& operator*() { return value_; }
  const T& operator*() const { return value_; }
  T* operator->() { return &value_; }
  const T* operator->() const { return &value_; }
  T* get() { return &value_; }
  const T* get() const { return &value_; }

  const SampleMeta& meta() const { return meta_; }
  SampleMeta& meta() { return meta_; }

 private:
  void release() {
    detail::freeSampleContents(&value_, MessageTraits<T>::descriptor());
    value_ = T{};
  }

  T value_{};
  SampleMeta meta_{};
};

}  // namespace pool::net
