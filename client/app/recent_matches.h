// The lobby's history: matches this window saw played that have left the lobby since (finished,
// closed), newest first, so that their stored shots can still be replayed.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "client/net/lobby.h"

namespace pool::app {

/// A match seen with at least one shot, as the lobby last showed it (a player who left keeps
/// their name).
struct RecentMatch {
  client::LobbyEntry entry;
  bool in_lobby = true;  ///< still listed (false: gone: finished or closed)
};

/// The matches seen played, newest first, at most kKept (the oldest give way).
class RecentMatches {
 public:
  static constexpr std::size_t kKept = 16;

  /// Looks at the lobby: a match with shots is remembered (its entry updated while listed); one
  /// remembered and no longer listed is gone.
  void see(const client::Lobby& lobby);
  /// Those no longer in the lobby, newest first.
  std::vector<const client::LobbyEntry*> gone() const;

 private:
  std::deque<RecentMatch> matches_;  ///< newest first
};

}  // namespace pool::app
