// The lobby pool-web keeps and serves, bounded per server id and in total: a flood of entries
// never grows its memory or a browser's first message, and a new server id never takes entries
// from one holding as few.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "client/net/match_types.h"

namespace pool::web {

struct LobbyLimits {
  std::size_t per_server = 256;         ///< entries kept per server id
  std::size_t kept = 4096;              ///< entries kept in all
  std::size_t served = 4096;            ///< entries in the lobby message
  std::size_t served_bytes = 1u << 20;  ///< bytes of the lobby message
};

/// The lobby entries, by match id, as the gateway keeps them. Where a bound bites, the server id
/// holding the most entries gives up its highest-numbered first (of two holding as many, the one
/// seen later), so an id flooding entries crowds out only itself.
class BoundedLobby {
 public:
  explicit BoundedLobby(LobbyLimits limits = {}) : limits_(limits) {}

  /// Adds or replaces the entry of `entry.match`. A new match is not kept (false) when its server
  /// id has per_server entries already, or when the lobby is full and no server id holds at least
  /// two more than its own (otherwise that one's highest-numbered entry makes room).
  bool update(const client::LobbyEntry& entry);
  void remove(const std::string& match);
  const client::LobbyEntry* find(const std::string& match) const;
  std::size_t size() const { return entries_.size(); }
  /// New matches not kept so far.
  std::uint64_t refused() const { return refused_; }

  /// The lobby message (web_json's lobbyJson), lowest-numbered first, of at most `served` entries
  /// and `served_bytes` bytes: the server ids holding the most give up their highest-numbered
  /// entries first.
  std::string message() const;

 private:
  struct Kept {
    client::LobbyEntry entry;
    std::string json;  ///< lobbyEntryJson(entry)
  };
  struct MatchLess {
    bool operator()(const std::string& a, const std::string& b) const;
  };
  struct Server {
    std::set<std::string, MatchLess> matches;
    std::uint64_t seen = 0;  ///< when this id was first kept (a counter)
  };

  void add(const client::LobbyEntry& entry);
  /// The server id whose entries go first: the most entries, then the one seen later.
  std::map<std::string, Server>::iterator heaviest();

  LobbyLimits limits_;
  std::map<std::string, Kept> entries_;
  std::map<std::string, Server> servers_;
  std::uint64_t next_seen_ = 0;
  std::uint64_t refused_ = 0;
};

}  // namespace pool::web
