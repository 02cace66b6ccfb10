// What the server publishes of a match, as the protocol's messages: lobby entry, state, command
// answers, frames and join replies (server/ never builds a wire sample itself).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "physics/simulation.h"
#include "protocol/command_limits.h"
#include "protocol/match_messages.h"
#include "server/match/join.h"
#include "server/match/match.h"
#include "server/match/match_types.h"
#include "table/table_spec.h"

namespace pool::server {

/// The lobby entry of `match`, run by server `server_id`.
protocol::LobbyEntry lobbyEntryOf(const Match& match, const std::string& server_id);

/// The state of `match` between shots, with its balls at rest, and its shot clock at `now` (s, the
/// server's clock; none without it).
protocol::MatchView matchViewOf(const Match& match, std::optional<double> now = {});

/// The answer to a command as soon as it is judged: a refusal (with its reason), or an accepted
/// shot whose motion is about to be published (no events or verdict yet; verdict_text empty).
protocol::ShotReport commandReport(const std::string& match, const CommandAnswer& answer);

/// The final answer to an accepted command: its events and the verdict (verdict_text set).
protocol::ShotReport finalReport(const std::string& match, const ShotReport& report);

/// Frame `frame` of shot `shot_number` of `match`.
protocol::TableFrame frameOf(const std::string& match, std::uint32_t frame,
                             std::uint32_t shot_number, const physics::Sample& at);

/// The reply to `command`.
protocol::JoinAnswer replyTo(const JoinCommand& command, const JoinAnswer& answer,
                             const std::string& server_id);

/// The wire limits of a command on `spec`'s table (speed, elevation, miscue, playing surface).
protocol::CommandLimits commandLimits(const table::TableSpec& spec);
/// The wire limits of a command at a server whose pool table is `pool_table`: that table's,
/// with the playing surface of the largest table a game is played on (snooker's, the carom
/// table), since one check reads every command before it reaches its match (which checks a spot
/// on its own table). A table whose spec cannot load is left out: its games cannot start here.
protocol::CommandLimits serverLimits(const table::TableSpec& pool_table);

}  // namespace pool::server
