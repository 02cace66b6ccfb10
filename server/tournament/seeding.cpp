// Seeding: ratings to seeds, and seeds to bracket positions by the usual recursive order.
#include "server/tournament/seeding.h"

#include <algorithm>
#include <numeric>

namespace pool::tournament {

std::vector<int> seedOrder(const std::vector<Entrant>& entrants) {
  std::vector<int> order(entrants.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return entrants[x].rating > entrants[y].rating; });
  return order;
}

int bracketSize(int count) {
  int size = 1;
  while (size < count) size *= 2;
  return size;
}

std::vector<int> bracketOrder(int size) {
  std::vector<int> order = {1};
  for (int n = 1; n < size; n *= 2) {
    std::vector<int> next;
    next.reserve(order.size() * 2);
    for (const int s : order) {
      next.push_back(s);
      next.push_back(2 * n + 1 - s);
    }
    order = std::move(next);
  }
  return order;
}

}  // namespace pool::tournament
