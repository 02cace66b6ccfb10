// Why the server refused a shot command: the reasons of pool.idl's RejectReason, in domain terms.
#pragma once

#include <cstdint>
#include <string>

#include "core/check.h"
#include "protocol/protocol_enums.h"

namespace pool::server {

/// Why a command was refused, in the order the server checks (shared with the clients).
using Reject = protocol::RejectReason;

/// A check of a command: it passes, or refuses with the reason and one human-readable line.
using RejectCheck = Check<Reject>;

/// A refusal as an answer carries it: the reason and one human-readable line.
struct Rejection {
  Reject reason = Reject::None;
  std::string text;  ///< empty when accepted

  bool accepted() const { return reason == Reject::None; }
  static Rejection none() { return {}; }
};

}  // namespace pool::server
