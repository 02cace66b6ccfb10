// A player's rating and statistics in one game as the window's Players table shows them.
#pragma once

#include <array>
#include <string>

#include "protocol/player_stats.h"

namespace pool::app {

inline constexpr std::size_t kPlayerColumns = 11;

/// The table's headers: server, player, game, rating, matches, racks, pots, breaks, fouls,
/// safeties, best.
const std::array<const char*, kPlayerColumns>& playerHeaders();

/// One row: "srv", "Ada", "9-ball", "1562 ±80", "2/3" (matches won of played), "5/7" (racks),
/// "45/60 75%" (balls potted of attempts; snooker and three-cushion: "145/90, 1.61 a stroke",
/// points), "4: 6, 1 run" (breaks: balls potted on them, break-and-runs), "3", "2", "8" (best
/// inning: balls, snooker's highest break, three-cushion's high run).
std::array<std::string, kPlayerColumns> playerColumns(const protocol::PlayerStats& stats);

}  // namespace pool::app
