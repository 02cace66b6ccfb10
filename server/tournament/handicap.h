// Handicaps of a tournament's matches: racks on the wire for the lower-rated player, chosen so
// that the race is as close to even as the two ratings say.
#pragma once

#include <array>

namespace pool::tournament {

/// The chance that a player rated `rating` beats one rated `other` in one rack when the two
/// ratings together are uncertain by `deviation` (rating points; the root of the sum of the two
/// deviations' squares): Glickman's expectation 1 / (1 + 10^(-g(φ)(rating - other) / 400)) with
/// g(φ) = 1 / sqrt(1 + 3φ²/π²), φ = deviation / 173.7178 ("Example of the Glicko-2 system",
/// E and g): uncertain ratings promise less, so fresh keys get smaller spots.
double rackChance(double rating, double other, double deviation = 0.0);

/// The chance that a player who wins each rack with probability `p` (independently) wins `need`
/// racks before the other wins `other_need` (the negative binomial sum
/// Σ_{j<other_need} C(need-1+j, j) p^need (1-p)^j). 1 when need is 0; 0 when other_need is 0.
double raceChance(double p, int need, int other_need);

/// A rating and its deviation (Glicko-2, rating points).
struct RatedEntrant {
  double rating = 1500.0;
  double deviation = 0.0;
};

/// The racks on the wire (seat a, seat b) for a race to `race_to` between entrants `a` and `b`:
/// the lower-rated player starts with the spot s (0..race_to-1) that brings their chance of
/// winning the race (raceChance with need race_to - s, each rack's chance rackChance of the two
/// ratings and their combined deviation) closest to 1/2, the smaller spot on a tie; the other
/// starts with none. Equal ratings, or a race to 1: no spot.
std::array<int, 2> handicapSpots(RatedEntrant a, RatedEntrant b, int race_to);

}  // namespace pool::tournament
