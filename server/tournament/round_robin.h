// Round robin: the circle-method schedule, and the ranking by wins and its tie-breaks.
#pragma once

#include "server/tournament/match.h"

#include <vector>

namespace pool::tournament {

/// The matches of a round robin for `bySeed` (entrant indices, seed 1 first), round by round
/// ("R1", "R2", ...; stage = round number) by the circle method: the seeds stand in a circle
/// (plus an empty place, a bye, when their number is odd), place 0 holds still and the others turn
/// one step a round; each round pairs place i with place n-1-i. N entrants: N(N-1)/2 matches in
/// N-1 rounds (N rounds when N is odd), nobody twice in a round.
std::vector<Match> buildRoundRobin(const std::vector<int>& bySeed);

/// The entrants best first, by the Done matches. The rule, key by key:
///   1. wins (a forfeit is a win for the one who stayed);
///   2. among the entrants level on wins, the wins in the matches between them (a mini-table of
///      all of them: for two that is their head-to-head result);
///   3. rack difference, racks won minus racks lost over all matches (a forfeit counts no racks);
///   4. seed (the better seed first).
/// The mini-table is not applied again to a subset still level after it: key 3 decides.
/// `seeds[e]` is entrant e's seed (1 is best).
std::vector<int> rankRoundRobin(const std::vector<Match>& matches, const std::vector<int>& seeds);

}  // namespace pool::tournament
