// Round robin: the circle method's schedule, and the ranking by wins, mini-table, racks and seed.
#include "server/tournament/round_robin.h"

#include "server/tournament/standings.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace pool::tournament {

std::vector<Match> buildRoundRobin(const std::vector<int>& bySeed) {
  const int count = static_cast<int>(bySeed.size());
  const int places = count % 2 == 0 ? count : count + 1;  // the last is a bye when count is odd
  std::vector<int> circle(places);
  std::iota(circle.begin(), circle.end(), 0);  // seed positions: circle[i] - 1 < count or a bye
  std::vector<Match> matches;
  for (int round = 1; round < places; ++round) {
    for (int i = 0; i < places / 2; ++i) {
      const int x = circle[i];
      const int y = circle[places - 1 - i];
      if (x >= count || y >= count) continue;
      Match m;
      m.index = static_cast<int>(matches.size());
      m.round = "R" + std::to_string(round);
      m.stage = round;
      m.a = bySeed[x];
      m.b = bySeed[y];
      m.state = MatchState::Ready;
      matches.push_back(m);
    }
    std::rotate(circle.begin() + 1, circle.end() - 1, circle.end());
  }
  return matches;
}

std::vector<int> rankRoundRobin(const std::vector<Match>& matches, const std::vector<int>& seeds) {
  const int count = static_cast<int>(seeds.size());
  const std::vector<Standing> records = tally(count, matches);
  std::vector<int> miniWins(count, 0);  // wins against entrants level on wins
  for (const Match& m : matches) {
    if (m.state != MatchState::Done) continue;
    if (records[m.a].wins == records[m.b].wins) ++miniWins[m.winner];
  }
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    const Standing& rx = records[x];
    const Standing& ry = records[y];
    if (rx.wins != ry.wins) return rx.wins > ry.wins;
    if (miniWins[x] != miniWins[y]) return miniWins[x] > miniWins[y];
    const int dx = rx.racksWon - rx.racksLost;
    const int dy = ry.racksWon - ry.racksLost;
    if (dx != dy) return dx > dy;
    return seeds[x] < seeds[y];
  });
  return order;
}

}  // namespace pool::tournament
