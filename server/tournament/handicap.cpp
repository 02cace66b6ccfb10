// Racks on the wire from two ratings: the spot that makes the race closest to even.
#include "server/tournament/handicap.h"

#include <cmath>
#include <numbers>

namespace pool::tournament {

double rackChance(double rating, double other, double deviation) {
  constexpr double kScale = 173.7178;  // Glicko-2's rating points per unit of μ
  const double phi = deviation / kScale;
  const double g = 1.0 / std::sqrt(1.0 + 3.0 * phi * phi / (std::numbers::pi * std::numbers::pi));
  return 1.0 / (1.0 + std::pow(10.0, -g * (rating - other) / 400.0));
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

std::array<int, 2> handicapSpots(RatedEntrant a, RatedEntrant b, int race_to) {
  if (race_to <= 1 || a.rating == b.rating) return {0, 0};
  const bool a_weaker = a.rating < b.rating;
  const double deviation = std::hypot(a.deviation, b.deviation);
  const double p = a_weaker ? rackChance(a.rating, b.rating, deviation)
                            : rackChance(b.rating, a.rating, deviation);
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
