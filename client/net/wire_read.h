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
#include "protocol/seat_request.h"

namespace pool::client {

Result<LobbyEntry> fromWire(const pool_MatchInfo& info);
Result<JoinAnswer> fromWire(const pool_JoinReply& reply);
Result<MatchView> fromWire(const pool_MatchState& state);
Result<ShotReport> fromWire(const pool_ShotResult& result);
Result<TableFrame> fromWire(const pool_TableSnapshot& snapshot);

/// A JoinRequest sample (text cut to its bounds, key and signature to theirs).
net::Sample<pool_JoinRequest> toWire(const protocol::SeatRequest& request);

}  // namespace pool::client
