// Racks on the wire from two ratings: the spot that makes the race closest to even.
#include "server/tournament/handicap.h"

#include <cmath>

namespace pool::tournament {

double rackChance(double rating, double other) {
  return 1.0 / (1.0 + std::pow(10.0, (other - rating) / 400.0));
}

double raceChance(double p, int need, int other_need) {
  if (need <= 0) return 1.0;
  if (other_need <= 0) return 0.0;
  // Win the last rack with `need - 1` won and j lost before it, for each j < other_need.
  double total = 0.0;
  double ways = 1.0;  // C(need - 1 + j, j), built up j by j
  for (int j = 0; j < other_need; ++j) {
    if (j > 0) ways = ways * (need - 1 + j) / j;
    total += ways * std::pow(p, need) * std::pow(1.0 - p, j);
  }
  return total;
}

std::array<int, 2> handicapSpots(double rating_a, double rating_b, int race_to) {
  if (race_to <= 1 || rating_a == rating_b) return {0, 0};
  const bool a_weaker = rating_a < rating_b;
  const double p = a_weaker ? rackChance(rating_a, rating_b) : rackChance(rating_b, rating_a);
  int best = 0;
  double best_gap = 1.0;
  for (int spot = 0; spot < race_to; ++spot) {
    const double gap = std::abs(raceChance(p, race_to - spot, race_to) - 0.5);
    if (gap < best_gap - 1e-12) {
      best_gap = gap;
      best = spot;
    }
  }
  return a_weaker ? std::array<int, 2>{best, 0} : std::array<int, 2>{0, best};
}

}  // namespace pool::tournament
