// Checks a stored match against the rules engine: shot numbers, re-judged verdicts, the winner.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "game/loaded_table.h"
#include "rules/game_rules.h"
#include "server/store/match_store.h"

namespace pool::store {

/// What auditMatch found.
struct Audit {
  std::uint32_t shots = 0;         ///< stored shots (commands with a shot) re-judged
  std::uint32_t choices = 0;       ///< stored choices without a shot
  int winner = -1;                 ///< the seat the last re-judged verdict gives the game to, or -1
  std::array<int, 2> racks{0, 0};  ///< racks each seat won in the re-judged verdicts
  std::vector<std::string> problems;  ///< one line each; empty: the match is sound

  bool sound() const { return problems.empty(); }
};

/// Re-judges every stored shot of match `id` from its stored state, table, intent and event log
/// with the rules engine (`rules` as the server played them on `kit`), and checks: shot numbers run
/// 1, 2, ... without gaps or repeats; each verdict (and the state it leads to) is the stored one;
/// the match's stored shot count, and its winner once the game is over, agree with the shots.
Audit auditMatch(MatchStore& store, const std::string& id, const game::LoadedTable& kit,
                 const rules::EightBallConfig& rules = {});

}  // namespace pool::store
