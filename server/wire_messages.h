// Outgoing messages built from matches: lobby entries, states, results, frames, replies.
#pragma once

#include <cstdint>
#include <string>

#include "match/join.h"
#include "match/match.h"
#include "match/match_types.h"
#include "net/messages.h"
#include "net/sample.h"
#include "physics/simulation.h"

namespace pool::server {

/// The lobby entry of `match`, run by server `server_id`.
pool_MatchInfo matchInfo(const Match& match, const std::string& server_id);

/// The state of `match` between shots, with its balls at rest.
net::Sample<pool_MatchState> matchState(const Match& match);

/// The answer to a command as soon as it is judged: a refusal (with its reason), or an accepted
/// shot whose motion is about to be published (no events or verdict yet; verdict_text empty).
net::Sample<pool_ShotResult> commandResult(const std::string& match, const CommandAnswer& answer);

/// The final answer to an accepted command: its events and the verdict (verdict_text set).
net::Sample<pool_ShotResult> finalResult(const std::string& match, const ShotReport& report);

/// Frame `frame` of shot `shot_number` of `match`.
net::Sample<pool_TableSnapshot> snapshot(const std::string& match, std::uint32_t frame,
                                         std::uint32_t shot_number, const physics::Sample& at);

/// The reply to `command`.
pool_JoinReply joinReply(const JoinCommand& command, const JoinAnswer& answer,
                         const std::string& server_id);

}  // namespace pool::server
