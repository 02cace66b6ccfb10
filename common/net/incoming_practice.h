// A practice command as the server reads it off the wire, in domain terms: the request, or why
// its fields cannot be read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "protocol/practice_request.h"

namespace pool::net {

/// A practice command off the wire: its request once its fields check out, else the problem (the
/// match, seat and seq are echoed in the refusal either way).
struct IncomingPractice {
  std::string match;
  int seat = 0;
  std::uint32_t seq = 0;
  std::optional<protocol::PracticeRequest> request;
  bool bad_signature = false;  ///< the signature field itself is malformed (over 64 bytes)
  std::string problem;         ///< "<field>: <reason>" when `request` is empty
};

}  // namespace pool::net
