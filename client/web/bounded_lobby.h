// The lobby pool-web keeps (client::Lobby's bounds) and serves, cut to a browser's first message.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "client/net/lobby.h"
#include "client/net/match_types.h"

namespace pool::web {

/// What the gateway keeps (client::LobbyBounds: per server id and in all) and serves.
struct LobbyLimits : client::LobbyBounds {
  std::size_t served = 4096;            ///< entries in the lobby message
  std::size_t served_bytes = 1u << 20;  ///< bytes of the lobby message
};

/// The lobby entries, by match id, as the gateway keeps them: a client::Lobby with its bounds (an
/// id flooding entries crowds out only itself), and each entry's JSON ready to serve.
class BoundedLobby {
 public:
  explicit BoundedLobby(LobbyLimits limits = {}) : limits_(limits), lobby_(limits) {}

  /// Adds or replaces the entry of `entry.match`; false when the bounds refuse a new match (see
  /// client::Lobby::update).
  bool update(const client::LobbyEntry& entry);
  void remove(const std::string& match);
  const client::LobbyEntry* find(const std::string& match) const { return lobby_.find(match); }
  std::size_t size() const { return lobby_.size(); }
  /// New matches not kept so far.
  std::uint64_t refused() const { return lobby_.refused(); }

  /// The lobby message (web_json's lobbyJson), lowest-numbered first, of at most `served` entries
  /// and `served_bytes` bytes: the server ids holding the most give up their highest-numbered
  /// entries first.
  std::string message() const;

 private:
  LobbyLimits limits_;
  client::Lobby lobby_;
  std::map<std::string, std::string> json_;  ///< lobbyEntryJson of each kept entry, by match
};

}  // namespace pool::web
