// The ratings the store keeps: each player's Glicko-2 rating per game, and rating a decided match.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rules/game_rules.h"
#include "server/match/match_snapshot.h"
#include "server/rating/glicko2.h"
#include "server/store/sqlite_db.h"

namespace pool::store {

/// One rated result as stored: the match, the rack and shot that decided it, the game, both
/// players' keys and their ratings before and after.
struct RatedResult {
  std::string match;
  std::uint32_t rack = 0;
  std::uint32_t shot_number = 0;
  rules::Game game = rules::Game::EightBall;
  std::vector<std::uint8_t> winner_key, loser_key;
  double winner_before = 0.0, winner_after = 0.0;
  double loser_before = 0.0, loser_after = 0.0;
};

/// Whether `match` counts for the ratings: decided (its game over with a winner), not a practice
/// table, and its seats signed by two different keys. Bots are rated like anyone (a bot is a
/// player with a key of its own); hot-seat play (one key at both seats) and unsigned seats are
/// not.
bool isRated(const server::MatchSnapshot& match);

/// The rating `key` holds in `game`; a new player's (1500, 350, 0.06) when it holds none.
rating::Rating ratingOf(Database& db, const std::vector<std::uint8_t>& key, rules::Game game);

/// Rates `match` once it is decided: both players' Glicko-2 ratings after the match
/// (rating::afterMatch, the match a rating period of its own) and the result, written in the
/// caller's transaction. Nothing when the match is not rated or this decision already was (a
/// rematch is a new decision). True when it wrote.
bool rateDecided(Database& db, const server::MatchSnapshot& match);

/// The rated results of `match`, oldest first.
std::vector<RatedResult> ratedResults(Database& db, const std::string& match);

}  // namespace pool::store
