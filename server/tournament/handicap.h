// Handicaps of a tournament's matches: racks on the wire for the lower-rated player, chosen so
// that the race is as close to even as the two ratings say.
#pragma once

#include <array>

namespace pool::tournament {

/// The chance that a player rated `rating` beats one rated `other` in one rack: the Elo and
/// Glicko expectation 1 / (1 + 10^((other - rating) / 400)) (Glickman, "Example of the Glicko-2
/// system", E with g(φ) = 1: the deviations are left out, a handicap is set on the ratings).
double rackChance(double rating, double other);

/// The chance that a player who wins each rack with probability `p` (independently) wins `need`
/// racks before the other wins `other_need` (the negative binomial sum
/// Σ_{j<other_need} C(need-1+j, j) p^need (1-p)^j). 1 when need is 0; 0 when other_need is 0.
double raceChance(double p, int need, int other_need);

/// The racks on the wire (seat a, seat b) for a race to `race_to` between entrants rated
/// `rating_a` and `rating_b`: the lower-rated player starts with the spot s (0..race_to-1) that
/// brings their chance of winning the race (raceChance with need race_to - s) closest to 1/2,
/// the smaller spot on a tie; the other starts with none. Equal ratings, or a race to 1: no spot.
std::array<int, 2> handicapSpots(double rating_a, double rating_b, int race_to);

}  // namespace pool::tournament
