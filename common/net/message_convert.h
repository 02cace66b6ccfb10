// The protocol's messages (common/protocol) to and from their wire samples of pool.idl. Every value
// from the network is checked; what does not fit is a failure, never an assert.
#pragma once

#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"
#include "protocol/match_messages.h"
#include "protocol/seat_request.h"

namespace pool::net {

/// A lobby entry (MatchInfo).
Sample<pool_MatchInfo> toWire(const protocol::LobbyEntry& entry);
Result<protocol::LobbyEntry> fromWire(const pool_MatchInfo& info);

/// A join request: text cut to its bounds, key and signature to theirs. Reading fails on an
/// unknown action or unterminated text.
Sample<pool_JoinRequest> toWire(const protocol::SeatRequest& request);
Result<protocol::SeatRequest> fromWire(const pool_JoinRequest& request);

/// The answer to a join request (JoinReply).
Sample<pool_JoinReply> toWire(const protocol::JoinAnswer& answer);
Result<protocol::JoinAnswer> fromWire(const pool_JoinReply& reply);

/// A match between shots (MatchState).
Sample<pool_MatchState> toWire(const protocol::MatchView& view);
Result<protocol::MatchView> fromWire(const pool_MatchState& state);

/// A shot command's answer (ShotResult).
Sample<pool_ShotResult> toWire(const protocol::ShotReport& report);
Result<protocol::ShotReport> fromWire(const pool_ShotResult& result);

/// One frame of a shot (TableSnapshot).
Sample<pool_TableSnapshot> toWire(const protocol::TableFrame& frame);
Result<protocol::TableFrame> fromWire(const pool_TableSnapshot& snapshot);

}  // namespace pool::net
