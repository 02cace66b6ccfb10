// The players' statistics and ratings as a client received them (PlayerStats), bounded.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "protocol/player_stats.h"

namespace pool::client {

/// The most players' records a client keeps (per server, key and game); past it the oldest
/// received goes.
inline constexpr std::size_t kMaxPlayerRecords = 512;

/// Each player's latest record per server and game.
class PlayerBook {
 public:
  /// Keeps `stats` (replacing that player's earlier record of the same server and game).
  void update(protocol::PlayerStats stats);
  /// Every record, the best rated first (then by name).
  std::vector<const protocol::PlayerStats*> records() const;
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
