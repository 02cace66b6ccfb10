// Standings: each entrant's record (wins, losses, racks) and final place.
#pragma once

#include "server/tournament/match.h"

#include <vector>

namespace pool::tournament {

struct Standing {
  int entrant = 0;
  int place = 0;  ///< 1 is first; shared in elimination (two 3rds for "3rd-4th")
  int wins = 0;   ///< matches won, forfeits included
  int losses = 0;
  int racksWon = 0;  ///< racks of played matches (a forfeit counts none)
  int racksLost = 0;
};

/// Each entrant's record from the Done matches, in entrant order; places left 0.
std::vector<Standing> tally(int entrantCount, const std::vector<Match>& matches);

/// Elimination places: an entrant knocked out at a stage shares the place after everyone knocked
/// out later and everyone still in (1 + their number); the champion, and until the end everyone
/// still in, is 1st. So a single-elimination final's loser is 2nd, its semi-finals' losers share
/// 3rd, its quarter-finals' share 5th. Sorted by place, then seed.
std::vector<Standing> eliminationStandings(const std::vector<Match>& matches,
                                           const std::vector<int>& seeds);

/// Round-robin places, 1 to N without ties, by rankRoundRobin().
std::vector<Standing> roundRobinStandings(const std::vector<Match>& matches,
                                          const std::vector<int>& seeds);

}  // namespace pool::tournament
