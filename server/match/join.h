// Joining, watching and leaving matches, in domain terms (JoinRequest / JoinReply of pool.idl).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "net/protocol_enums.h"

namespace pool::server {

using net::JoinAction;   ///< what a JoinRequest asks for (shared with the clients)
using net::JoinOutcome;  ///< its outcome

/// The match id that asks for a new match.
inline constexpr const char* kNewMatch = "new";

/// A client's request.
struct JoinCommand {
  std::string client;         ///< the client's id
  std::uint32_t request = 0;  ///< echoed in the answer
  std::uint32_t protocol_version = 0;
  std::string match;  ///< a match id, or kNewMatch
  JoinAction action = JoinAction::Seat;
  int seat = -1;                         ///< Seat: 0, 1 or -1 (any)
  std::string name;                      ///< the player's name (Seat)
  std::uint64_t token = 0;               ///< Rejoin, Leave, Rematch: the seat's token
  std::vector<std::uint8_t> public_key;  ///< Seat, Rejoin: the Ed25519 key commands are signed with
};

/// The server's answer.
struct JoinAnswer {
  JoinOutcome outcome = JoinOutcome::Accepted;
  std::string reason;       ///< one line; empty when accepted
  std::string match;        ///< the match concerned (the new one for kNewMatch)
  int seat = -1;            ///< the seat taken; -1 for spectators and refusals
  std::uint64_t token = 0;  ///< the seat's token; 0 for spectators and refusals

  bool accepted() const { return outcome == JoinOutcome::Accepted; }
  static JoinAnswer refuse(JoinOutcome outcome, std::string reason) {
    return {outcome, std::move(reason), {}, -1, 0};
  }
};

}  // namespace pool::server
