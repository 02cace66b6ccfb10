// Elimination brackets: the matches of single and double elimination, wired match to match.
#pragma once

#include "server/tournament/match.h"

#include <vector>

namespace pool::tournament {

/// The matches of a single-elimination bracket for the entrants `bySeed` (entrant indices, seed 1
/// first): a bracket of the next power of two, seeds placed by bracketOrder(). Byes (positions
/// past the field) go to the top seeds, who stand directly in the second round: a bye is no match.
/// Rounds are named from the end: "F", "SF", "QF", earlier ones "R<n>". Stage = round number.
std::vector<Match> buildSingleElimination(const std::vector<int>& bySeed);

/// The matches of a double-elimination bracket for `bySeed`. The winners' bracket ("WB R<n>") is
/// the single-elimination one; each of its losers drops into the losers' bracket ("LB R<n>"): LB
/// R1 pairs the losers of WB R1, then each even LB round meets the losers of the next WB round
/// (in reversed order every other time, to put off rematches) and each odd one pairs the
/// survivors. The grand final ("GF") sets the winners' bracket champion (a) against the losers'
/// (b); if b wins it, the tournament adds a bracket reset ("GF reset"), as WPA double-elimination
/// events do, so nobody is out before two losses. Stage = LB round number (the grand final one
/// past the last); the winners' bracket knocks nobody out.
std::vector<Match> buildDoubleElimination(const std::vector<int>& bySeed);

}  // namespace pool::tournament
