// One match of a tournament: its entrants, state and result, and where its winner and loser go.
#pragma once

#include <cstdint>
#include <string>

namespace pool::tournament {

enum class MatchState : std::uint8_t {
  Waiting,  ///< an entrant is not known yet (the winner or loser of an earlier match)
  Ready,    ///< both entrants known; not started
  InPlay,   ///< started (Tournament::start), not reported
  Done,     ///< reported, or decided by a forfeit
};

enum class MatchKind : std::uint8_t {
  Regular,
  GrandFinal,       ///< double elimination: winners' bracket champion (a) v losers' (b)
  GrandFinalReset,  ///< played only when b won the grand final
};

/// Where a match's winner or loser goes: side 0 of match `match` is its entrant a, side 1 its b.
/// match -1: nowhere (the winner is the champion, or the loser is out).
struct Slot {
  int match = -1;
  int side = 0;
};

struct Match {
  int index = 0;           ///< the match's number: its place in Tournament::matches(), for good
  std::string round = {};  ///< "R1", "QF", "SF", "F"; "WB R1", "LB R2", "GF", "GF reset"
  MatchKind kind = MatchKind::Regular;
  int stage = 0;  ///< entrants knocked out here place above those of earlier stages
  int a = -1;     ///< entrant index; -1 while not known
  int b = -1;
  MatchState state = MatchState::Waiting;
  int winner = -1;  ///< entrant index once Done
  int racksA = 0;   ///< racks won by a, and by b (both 0 when decided by a forfeit)
  int racksB = 0;
  bool forfeit = false;  ///< decided because an entrant left, not played
  Slot winnerTo = {};
  Slot loserTo = {};

  /// The entrant who lost; -1 until Done.
  int loser() const { return winner < 0 ? -1 : (winner == a ? b : a); }
  bool has(int entrant) const { return entrant >= 0 && (a == entrant || b == entrant); }
};

}  // namespace pool::tournament
