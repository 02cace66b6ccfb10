// The players' statistics and ratings as a client received them (PlayerStats), bounded.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "protocol/player_stats.h"

namespace pool::client {

/// The most players' records a client keeps (per server, key and game), in all and of one server
/// id; past either the oldest received (of that server) goes, so one server id's flood of
/// records (anyone may sign as a server id of their own) cannot push out another's.
inline constexpr std::size_t kMaxPlayerRecords = 1024;
inline constexpr std::size_t kMaxPlayerRecordsPerServer = 256;

/// Each player's latest record per server and game.
class PlayerBook {
 public:
  /// Keeps `stats` (replacing that player's earlier record of the same server and game).
  void update(protocol::PlayerStats stats);
  /// Every record, the best rated first (then by name).
  std::vector<const protocol::PlayerStats*> records() const;
  /// At most `limit` records, shared out among the server ids in turn (each one's best rated
  /// first), so that no server id's records crowd out another's.
  std::vector<const protocol::PlayerStats*> fairShare(std::size_t limit) const;
  /// The records of the player named `name`, one per server and game.
  std::vector<const protocol::PlayerStats*> named(const std::string& name) const;
  std::size_t size() const { return records_.size(); }

 private:
  using Key = std::tuple<std::string, std::vector<std::uint8_t>, int>;
  struct Kept {
    protocol::PlayerStats stats;
    std::uint64_t order = 0;  ///< when received (larger: later)
  };
  std::map<Key, Kept> records_;
  std::uint64_t received_ = 0;
};

}  // namespace pool::client
