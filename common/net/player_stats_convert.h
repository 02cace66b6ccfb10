// A player's statistics (protocol::PlayerStats) to and from its wire sample, PlayerStats.
#pragma once

#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"
#include "protocol/player_stats.h"

namespace pool::net {

/// The sample of `stats` (counts past the wire's range are clamped; the server seals it).
Sample<pool_PlayerStats> toWire(const protocol::PlayerStats& stats);

/// A PlayerStats read back; fails on an unterminated text, a key that is not 64 hex digits or a
/// game this build does not know.
Result<protocol::PlayerStats> fromWire(const pool_PlayerStats& sample);

}  // namespace pool::net
