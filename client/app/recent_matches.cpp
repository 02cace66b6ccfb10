// Remembering the matches the lobby showed played, after they leave it.
#include "client/app/recent_matches.h"

#include <algorithm>

namespace pool::app {

void RecentMatches::see(const client::Lobby& lobby) {
  for (RecentMatch& m : matches_) m.in_lobby = lobby.find(m.entry.match) != nullptr;
  for (const client::LobbyEntry* e : lobby.entries()) {
    if (e->shot_number == 0) continue;
    const auto it = std::find_if(matches_.begin(), matches_.end(),
                                 [&](const RecentMatch& m) { return m.entry.match == e->match; });
    if (it != matches_.end()) {
      // A player who left keeps their name (and rating) in the history: who played it.
      client::LobbyEntry kept = *e;
      for (std::size_t seat = 0; seat < kept.players.size(); ++seat) {
        if (!kept.players[seat].empty() || it->entry.players[seat].empty()) continue;
        kept.players[seat] = it->entry.players[seat];
        kept.ratings[seat] = it->entry.ratings[seat];
      }
      it->entry = std::move(kept);
      continue;
    }
    matches_.push_front({*e, true});
    if (matches_.size() > kKept) matches_.pop_back();
  }
}

std::vector<const client::LobbyEntry*> RecentMatches::gone() const {
  std::vector<const client::LobbyEntry*> out;
  for (const RecentMatch& m : matches_) {
    if (!m.in_lobby) out.push_back(&m.entry);
  }
  return out;
}

}  // namespace pool::app
