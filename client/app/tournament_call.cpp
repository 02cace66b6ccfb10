// Finding the tournament match that calls a player to its table.
#include "client/app/tournament_call.h"

namespace pool::app {

std::optional<TournamentCall> tournamentCall(
    const std::map<std::string, protocol::TournamentView>& tournaments, const std::string& player,
    const std::set<std::string>& joined) {
  constexpr int kInPlay = 2;
  for (const auto& [id, view] : tournaments) {
    if (view.phase != protocol::TournamentPhase::Running) continue;
    const int me = view.entrantOf(player);
    if (me < 0 || view.entrants[static_cast<std::size_t>(me)].withdrawn) continue;
    for (const auto& m : view.matches) {
      if (m.state != kInPlay || m.match.empty() || joined.count(m.match)) continue;
      if (m.a != me && m.b != me) continue;
      const int other = m.a == me ? m.b : m.a;
      const bool known = other >= 0 && other < static_cast<int>(view.entrants.size());
      return TournamentCall{id, m.match, m.round,
                            known ? view.entrants[static_cast<std::size_t>(other)].name : ""};
    }
  }
  return std::nullopt;
}

}  // namespace pool::app
