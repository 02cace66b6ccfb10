// One player's statistics and rating in one game on one server, as the lobby's player pages show
// them (the PlayerStats topic; kept by the server's store).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rules/game_rules.h"

namespace pool::protocol {

/// A player's record in one game: the key it signs with, its rating and its counts.
struct PlayerStats {
  std::string server = {};             ///< the server that keeps it (empty in the store)
  std::vector<std::uint8_t> key = {};  ///< the player's public key
  rules::Game game = rules::Game::EightBall;
  std::string name = {};     ///< the name it last played under
  int rating = 0;            ///< Glicko-2, rounded (0: not given)
  int rating_deviation = 0;  ///< rounded
  int matches = 0;           ///< matches decided at the table (a forfeit is not counted)
  int matches_won = 0;
  int racks = 0;  ///< racks, frames or games decided at the table
  int racks_won = 0;
  int strokes = 0;         ///< strokes played (a choice without one is not counted)
  int attempts = 0;        ///< strokes that try to score: not breaks, safeties, push-outs
  int pots = 0;            ///< balls potted legally by those strokes (three-cushion: points)
  int breaks = 0;          ///< breaks (snooker's break-off, three-cushion's opening) played
  int break_pots = 0;      ///< balls potted legally on them (three-cushion: points)
  int break_and_runs = 0;  ///< racks won from one's own break, the opponent never at the table
  int fouls = 0;
  int safeties = 0;  ///< declared safeties
  /// The best inning: most balls potted (pool), the highest break (snooker's points), the high
  /// run (three-cushion's points).
  int high_run = 0;

  bool operator==(const PlayerStats&) const = default;
};

}  // namespace pool::protocol
