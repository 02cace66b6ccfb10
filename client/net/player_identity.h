// A player's lasting identity on this machine: the key pair that signs their seats' messages and
// the seat they hold, kept per player name in the user's config folder (owner-only).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "client/net/seat_file.h"
#include "core/result.h"
#include "protocol/key_pair.h"

namespace pool::client {

/// `$XDG_CONFIG_HOME/pool/players`, or `~/.config/pool/players`; empty when neither is set.
std::filesystem::path defaultIdentityDir();

/// The files of one player name in `dir`.
class PlayerIdentity {
 public:
  PlayerIdentity(std::filesystem::path dir, const std::string& name);

  /// The player's key pair, made (owner-only) the first time.
  Result<protocol::KeyPair> key() const;
  /// The seat last held, if any (a file that cannot be read counts as none).
  std::optional<SeatRecord> seat() const;
  /// Remembers `record` (empty string on success, else why not).
  std::string keepSeat(const SeatRecord& record) const;
  /// Forgets the seat (left, or no longer there).
  void forgetSeat() const;

 private:
  std::filesystem::path base_;  ///< dir / the name made safe for a file name
};

}  // namespace pool::client
