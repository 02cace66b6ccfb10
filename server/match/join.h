// Joining, watching and leaving matches, in domain terms (JoinRequest / JoinReply of pool.idl).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "protocol/protocol_enums.h"
#include "protocol/seat_request.h"

namespace pool::server {

using protocol::JoinAction;   ///< what a JoinRequest asks for (shared with the clients)
using protocol::JoinOutcome;  ///< its outcome

using protocol::kNewMatch;  ///< the match id that asks for a new match

/// A client's request (a JoinRequest in domain terms; protocol/seat_request.h says which are
/// signed).
using JoinCommand = protocol::SeatRequest;

/// The server's answer.
struct JoinAnswer {
  JoinOutcome outcome = JoinOutcome::Accepted;
  std::string reason;          ///< one line; empty when accepted
  std::string match;           ///< the match concerned (the new one for kNewMatch)
  int seat = -1;               ///< the seat taken; -1 for spectators and refusals
  std::uint64_t token = 0;     ///< the seat's token; 0 for spectators and refusals
  std::uint32_t last_seq = 0;  ///< the last seq the request's key used (signed requests)

  bool accepted() const { return outcome == JoinOutcome::Accepted; }
  static JoinAnswer refuse(JoinOutcome outcome, std::string reason) {
    return {outcome, std::move(reason), {}, -1, 0, 0};
  }
};

}  // namespace pool::server
