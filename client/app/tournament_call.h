// The tournament match that calls a player to its table: the first match in play of a bracket
// that draws their key, not joined yet.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>

#include "protocol/tournament_view.h"

namespace pool::app {

/// A match a tournament calls a player to.
struct TournamentCall {
  std::string tournament;
  std::string match;  ///< the server's match id (its seats kept for the drawn keys)
  std::string round;  ///< "SF", "WB R2", ...
  std::string opponent;
};

/// The first match in play (tournaments by id, matches in bracket order) that draws the player
/// with key `player` (lower-case hex) as a or b and whose id is not in `joined`; none when the
/// player is in no such match (or withdrawn from the tournament).
std::optional<TournamentCall> tournamentCall(
    const std::map<std::string, protocol::TournamentView>& tournaments, const std::string& player,
    const std::set<std::string>& joined);

}  // namespace pool::app
