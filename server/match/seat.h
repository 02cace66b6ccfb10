// One of a match's two seats: who sits there, their token, presence and command sequence.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pool::server {

/// A seat of a match. Free while `token` is 0.
struct Seat {
  std::string player;                    ///< the player's name; empty while free
  std::uint64_t token = 0;               ///< random, never 0 while taken; commands must carry it
  std::string client;                    ///< the client id that holds the seat (for presence)
  std::optional<double> away_since;      ///< s on the server's clock, while the player is gone
  std::uint32_t last_seq = 0;            ///< the last used sequence number (of a signed command)
  std::vector<std::uint8_t> public_key;  ///< Ed25519 key its commands are signed with; empty: none
  int fouls = 0;                         ///< fouls this rack
  int racks_won = 0;
  bool wants_rematch = false;

  bool taken() const { return token != 0; }
  bool connected() const { return taken() && !away_since; }
};

}  // namespace pool::server
