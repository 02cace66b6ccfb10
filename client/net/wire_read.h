// The client's conversions between wire samples of pool.idl and its domain types (match_types.h).
// Every value from the network is checked; what does not fit is a failure, never an assert.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "client/net/match_types.h"
#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"

namespace pool::client {

Result<LobbyEntry> fromWire(const pool_MatchInfo& info);
Result<JoinAnswer> fromWire(const pool_JoinReply& reply);
Result<MatchView> fromWire(const pool_MatchState& state);
Result<ShotReport> fromWire(const pool_ShotResult& result);
Result<TableFrame> fromWire(const pool_TableSnapshot& snapshot);

/// What goes into a JoinRequest.
struct JoinRequestFields {
  std::string client;
  std::uint32_t request = 0;
  std::string match;
  JoinAction action = JoinAction::Seat;
  int seat = -1;
  std::string name;
  std::uint64_t token = 0;
  std::vector<std::uint8_t> public_key;  ///< at most 32 bytes are sent
};

/// A JoinRequest sample (protocol version of this build; text cut to its bounds).
net::Sample<pool_JoinRequest> toWire(const JoinRequestFields& fields);

}  // namespace pool::client
