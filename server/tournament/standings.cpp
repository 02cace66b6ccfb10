// Standings: records tallied from the matches, places by elimination stage or round-robin rank.
#include "server/tournament/standings.h"

#include "server/tournament/round_robin.h"

#include <algorithm>

namespace pool::tournament {

std::vector<Standing> tally(int entrantCount, const std::vector<Match>& matches) {
  std::vector<Standing> table(entrantCount);
  for (int e = 0; e < entrantCount; ++e) table[e].entrant = e;
  for (const Match& m : matches) {
    if (m.state != MatchState::Done) continue;
    Standing& winner = table[m.winner];
    Standing& loser = table[m.loser()];
    ++winner.wins;
    ++loser.losses;
    const bool aWon = m.winner == m.a;
    winner.racksWon += aWon ? m.racksA : m.racksB;
    winner.racksLost += aWon ? m.racksB : m.racksA;
    loser.racksWon += aWon ? m.racksB : m.racksA;
    loser.racksLost += aWon ? m.racksA : m.racksB;
  }
  return table;
}

std::vector<Standing> eliminationStandings(const std::vector<Match>& matches,
                                           const std::vector<int>& seeds) {
  const int count = static_cast<int>(seeds.size());
  std::vector<Standing> table = tally(count, matches);
  constexpr int kStillIn = 1 << 30;
  std::vector<int> outAt(count, kStillIn);  // the stage each entrant was knocked out at
  for (const Match& m : matches) {
    if (m.state != MatchState::Done || m.loserTo.match >= 0) continue;
    // The winners' bracket champion who loses the grand final plays the reset.
    if (m.kind == MatchKind::GrandFinal && m.winner == m.b) continue;
    outAt[m.loser()] = m.stage;
  }
  for (Standing& s : table) {
    s.place = 1 + static_cast<int>(std::count_if(outAt.begin(), outAt.end(), [&](int stage) {
                return stage > outAt[s.entrant];
              }));
  }
  std::sort(table.begin(), table.end(), [&](const Standing& x, const Standing& y) {
    return x.place != y.place ? x.place < y.place : seeds[x.entrant] < seeds[y.entrant];
  });
  return table;
}

std::vector<Standing> roundRobinStandings(const std::vector<Match>& matches,
                                          const std::vector<int>& seeds) {
  const std::vector<Standing> records = tally(static_cast<int>(seeds.size()), matches);
  std::vector<Standing> table;
  for (const int e : rankRoundRobin(matches, seeds)) {
    table.push_back(records[e]);
    table.back().place = static_cast<int>(table.size());
  }
  return table;
}

}  // namespace pool::tournament
