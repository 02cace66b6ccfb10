// A tournament in words, as the window's lobby shows it (the page's tournaments.js says the same):
// its line, its entrants by seed and each match of its bracket.
#pragma once

#include <string>
#include <vector>

#include "protocol/tournament_view.h"

namespace pool::app {

/// "Friday cup: 8-ball, single elimination, race to 1 - running, 3 of 7 matches played" (or
/// "5/8 entered", "won by ann", "cancelled"; ", handicapped" after the race when it is).
std::string tournamentLine(const protocol::TournamentView& t);

/// One match of the bracket: "QF: ann v hal - ann won 1-0", "QF: ann v hal (hal +2) - in play at
/// srv-5" (hal started with two racks on the wire), "... —
/// next", "... - waiting"; `match` the table it is (or was) played at, `in_play` whether it is
/// being played now.
struct BracketLine {
  std::string text;
  std::string match;
  bool in_play = false;
};
std::vector<BracketLine> bracketLines(const protocol::TournamentView& t);

/// The entrants by seed (in entry order before the draw): "1. ann (1532)", with ", place 3" once
/// it is finished and ", withdrawn" for one who left.
std::vector<std::string> entrantLines(const protocol::TournamentView& t);

}  // namespace pool::app
