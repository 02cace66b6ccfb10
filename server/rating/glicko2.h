// Glicko-2 ratings (Glickman, "Example of the Glicko-2 system", 2013): a player's rating after
// games.
#pragma once

#include <span>
#include <utility>

namespace pool::rating {

/// A player's rating on the Glicko scale: the rating, its deviation (how uncertain it is) and the
/// volatility (how erratic the player's results are). A new player: 1500, 350, 0.06.
struct Rating {
  double rating = 1500.0;
  double deviation = 350.0;
  double volatility = 0.06;
};

/// One game of a rating period against `opponent`: `score` 1 for a win, 0 for a loss, 0.5 a draw.
struct GameResult {
  Rating opponent;
  double score = 0.0;
};

/// The system constant τ, which limits how fast the volatility changes (Glickman suggests 0.3 to
/// 1.2; smaller for games whose results are steadier).
inline constexpr double kTau = 0.5;

/// `player`'s rating after a rating period with `games` (each against the opponent's rating at
/// the period's start). No games: only the deviation grows, as time without play makes a rating
/// less certain.
Rating updated(const Rating& player, std::span<const GameResult> games, double tau = kTau);

/// Both players' ratings after one rated match, a rating period of its own: the winner's first.
std::pair<Rating, Rating> afterMatch(const Rating& winner, const Rating& loser, double tau = kTau);

}  // namespace pool::rating
