// A signed player command (a shot, a practice command) as the server reads it off the wire, in
// domain terms: the request, or why its fields cannot be read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "protocol/shot_request.h"

namespace pool::net {

/// A command off the wire: its request once its fields check out, else the problem (the match,
/// seat and seq are echoed in the refusal either way).
template <class Request>
struct IncomingSigned {
  std::string match;
  int seat = 0;
  std::uint32_t seq = 0;
  std::optional<Request> request;
  bool bad_signature = false;  ///< the signature field itself is malformed (not 64 bytes)
  std::string problem;         ///< "<field>: <reason>" when `request` is empty
  /// The DDS participant it came from, as IncomingJoin::sender names it: what a refusal's
  /// answer is charged to (the match and seat are the sender's to invent).
  std::string sender;
};

/// A shot command off the wire (its fields checked by validateShotCommand).
using IncomingCommand = IncomingSigned<protocol::ShotRequest>;

}  // namespace pool::net
