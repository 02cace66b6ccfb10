// The players' records the server publishes (PlayerStats): each seated player's statistics and
// rating after a stroke of theirs finishes, the most recent at start, and at most a bounded
// number kept for late readers.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "net/server_transport.h"
#include "server/match/match.h"
#include "server/store/match_store.h"

namespace pool::server {

/// The most players' records the server keeps published (per player and game); past it the one
/// published longest ago is withdrawn (a reader that has it keeps it).
inline constexpr std::size_t kMaxPublishedPlayers = 256;

/// Publishes players' records from the store, bounded.
class PlayerPublisher {
 public:
  PlayerPublisher(net::ServerTransport& transport, std::string server_id)
      : transport_(transport), server_(std::move(server_id)) {}

  /// The records of `match`'s two seated players in its game (when the store has them); the
  /// errors of the writes that failed.
  std::vector<std::string> publishSeats(store::MatchStore& store, const Match& match);
  /// The `limit` records most recently added to (at start).
  std::vector<std::string> publishRecent(store::MatchStore& store, std::size_t limit);
  /// Records published and still kept.
  std::size_t kept() const { return order_.size(); }

 private:
  std::string publish(store::MatchStore& store, protocol::PlayerStats stats);

  net::ServerTransport& transport_;
  std::string server_;
  std::deque<std::pair<std::vector<std::uint8_t>, int>> order_;  ///< key and game, oldest first
};

}  // namespace pool::server
