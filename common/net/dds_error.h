// How failures of the Cyclone DDS C API reach callers: exceptions at construction, a Status after.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace pool::net {

/// A Cyclone DDS call failed. Thrown only where an object cannot exist without the call succeeding
/// (creating a participant, topic, reader, writer, waitset) or where the failure is a programming
/// error (using a deleted entity). Never thrown because of what a peer sent.
class DdsError : public std::runtime_error {
 public:
  DdsError(const std::string& what, std::int32_t code);
  /// The DDS_RETCODE_* value (negative).
  std::int32_t code() const { return code_; }

 private:
  std::int32_t code_;
};

/// The outcome of an operation that may fail while the program runs normally (a write that timed
/// out on a full reliable queue): empty `error` means success.
struct Status {
  std::string error;  ///< e.g. "write: Timeout"; empty on success

  explicit operator bool() const { return error.empty(); }
  static Status ok() { return {}; }
};

}  // namespace pool::net
