// The statistics the store keeps: each player's counts per game, added to with every stored stroke.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocol/player_stats.h"
#include "rules/game_rules.h"
#include "server/match/match_snapshot.h"
#include "server/match/shot_record.h"
#include "server/store/sqlite_db.h"

namespace pool::store {

/// One player's statistics in one game on this server (its `server`, rating and deviation are
/// left 0 and empty: the caller adds them).
using PlayerStats = protocol::PlayerStats;

/// Whether `match` counts for the statistics: not a practice table, and its seats signed by two
/// different keys (hot-seat play and unsigned seats are not counted, as for the ratings).
bool countsForStats(const server::MatchSnapshot& match);

/// Adds the stroke or choice `record` to its shooter's statistics (and, when it decides a rack or
/// the match, to both players'), in the caller's transaction. `after`: the match as the record
/// left it. Nothing when the match does not count.
void countStroke(Database& db, const server::ShotRecord& record,
                 const server::MatchSnapshot& after);

/// `key`'s statistics in `game`; empty when it has none.
std::optional<PlayerStats> statsOf(Database& db, const std::vector<std::uint8_t>& key,
                                   rules::Game game);

/// The statistics most recently added to, newest first, at most `limit` of them.
std::vector<PlayerStats> recentStats(Database& db, std::size_t limit);

}  // namespace pool::store
