// The lobby as the client sees it: its open matches (MatchInfo), bounded, and which one to pick.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "client/net/match_types.h"

namespace pool::client {

/// Orders match ids "<server>-<number>" by their number, then by id (a bare id counts as 0).
bool matchOrder(const std::string& a, const std::string& b);

/// matchOrder as a comparison object, for ordered containers.
struct MatchOrder {
  bool operator()(const std::string& a, const std::string& b) const { return matchOrder(a, b); }
};

/// How many lobby entries are kept: a flood of entries never grows a client's memory past these.
struct LobbyBounds {
  std::size_t per_server = 256;  ///< entries kept per server id
  std::size_t kept = 4096;       ///< entries kept in all
};

/// What Lobby::update did with an entry.
struct LobbyUpdate {
  bool kept = false;     ///< the entry is kept (false: the bounds refused a new match)
  std::string gave_way;  ///< the match dropped to make room for it, if any
};

/// The open matches of every server on the domain, by match id, bounded per server id and in
/// all. Where a bound bites, the server id holding the most entries gives up its highest-numbered
/// first (of two holding as many, the one seen later), so an id flooding entries crowds out only
/// itself and a new server id never takes entries from one holding as few.
class Lobby {
 public:
  /// One server id's kept entries.
  struct Server {
    std::set<std::string, MatchOrder> matches;  ///< lowest-numbered first
    std::uint64_t seen = 0;                     ///< when this id was first kept (a counter)
  };

  explicit Lobby(LobbyBounds bounds = {}) : bounds_(bounds) {}

  /// Adds or replaces the entry of `entry.match`. An update of a kept match always passes. A new
  /// match is not kept when its server id has per_server entries already, or when the lobby is
  /// full and no server id holds at least two more than its own (otherwise that one's
  /// highest-numbered entry gives way).
  LobbyUpdate update(LobbyEntry entry);
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
  std::size_t size() const { return entries_.size(); }
  /// The kept entries' server ids.
  const std::map<std::string, Server>& servers() const { return servers_; }
  /// New matches not kept so far.
  std::uint64_t refused() const { return refused_; }

 private:
  /// The server id whose entries go first: the most entries, then the one seen later.
  std::map<std::string, Server>::iterator heaviest();

  LobbyBounds bounds_;
  std::map<std::string, LobbyEntry> entries_;
  std::map<std::string, Server> servers_;
  std::uint64_t next_seen_ = 0;
  std::uint64_t refused_ = 0;
};

}  // namespace pool::client
