// The lobby as the client sees it: every open match (MatchInfo), and which one to pick.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "client/net/match_types.h"

namespace pool::client {

/// The open matches of every server on the domain, by match id.
class Lobby {
 public:
  /// Adds or replaces the entry of `entry.match`.
  void update(LobbyEntry entry);
  /// Forgets a match (closed, or its server vanished).
  void remove(const std::string& match);

  const LobbyEntry* find(const std::string& match) const;
  /// Every entry, lowest-numbered first (see matchOrder).
  std::vector<const LobbyEntry*> entries() const;
  /// The lowest-numbered match not over or closed with a free seat, if any.
  std::optional<std::string> lowestWithFreeSeat() const;
  /// The lowest-numbered match with a rack in play, if any.
  std::optional<std::string> firstInPlay() const;
  bool empty() const { return entries_.empty(); }

 private:
  std::map<std::string, LobbyEntry> entries_;
};

/// Orders match ids "<server>-<number>" by their number, then by id (a bare id counts as 0).
bool matchOrder(const std::string& a, const std::string& b);

}  // namespace pool::client
