// Seeding: the field in seed order by rating, and the seeds' places in an elimination bracket.
#pragma once

#include "server/tournament/entrant.h"

#include <vector>

namespace pool::tournament {

/// The entrants' indices, best seed first: highest rating first, equal ratings in entry order.
std::vector<int> seedOrder(const std::vector<Entrant>& entrants);

/// The smallest power of two that is at least `count` (count >= 1): the size of a bracket.
int bracketSize(int count);

/// The seeds (1-based) of a bracket of `size` (a power of two, at least 2) by position, top to
/// bottom; the first round pairs positions 0-1, 2-3, and so on. The usual recursive order: the
/// order of size 2n puts each seed s of the order of size n beside 2n + 1 - s, so each pair of a
/// round sums to (its field size + 1), and seeds 1 and 2 can only meet in the final, seeds 1 to 4
/// only from the semi-finals on. Size 8: 1 8 4 5 2 7 3 6.
std::vector<int> bracketOrder(int size);

}  // namespace pool::tournament
