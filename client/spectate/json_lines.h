// The spectator's output: one compact JSON object per line for each state, result and shot's
// frame count.
#pragma once

#include <cstdint>
#include <string>

#include "client/net/match_types.h"

namespace pool::client {

/// {"type":"spectating","match":...,"server":...,"spectators":...}
std::string spectatingLine(const JoinAnswer& answer);
/// {"type":"match_state","match":...,"revision":...,"phase":...,"seats":[...],...}
std::string matchStateLine(const MatchView& view);
/// {"type":"shot_result","match":...,"seat":...,"seq":...,"accepted":...,"final":...,...}
std::string shotResultLine(const ShotReport& report);
/// {"type":"snapshots","match":...,"shot_number":...,"count":...,"first_frame":...,
/// "last_frame":...}
std::string snapshotsLine(const std::string& match, std::uint32_t shot_number, std::uint32_t count,
                          std::uint32_t first_frame, std::uint32_t last_frame);

}  // namespace pool::client
