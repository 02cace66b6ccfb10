// The server keys a client trusts: each server id's Ed25519 key, pinned the first time a sample
// signed by it arrives, kept in a file (owner-only) or in memory, forgotten on an operator's word.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>

#include "protocol/key_pair.h"

namespace pool::client {

/// `$XDG_CONFIG_HOME/pool/servers`, or `~/.config/pool/servers`; empty when neither is set.
std::filesystem::path defaultServerPinFile();

/// How a server's key compares with its pin.
enum class PinCheck : std::uint8_t {
  FirstSight,  ///< nothing was pinned for that server id: now this key is
  Same,        ///< the pinned key
  Changed,     ///< another key is pinned for that server id
  Refused      ///< not a server id a server may use, or no room for another pin
};

/// Server id -> pinned key. With a file, pins are read from it at construction and every new pin
/// is added to it (one line "<server id> <key in hex>", the file owner-only); without one they
/// last as long as the object. At most kMaxPins are kept (a flood of made-up server ids pins no
/// more; their samples are dropped).
class ServerPins {
 public:
  static constexpr std::size_t kMaxPins = 1024;

  /// Pins kept in `file` (empty: in memory only). Lines that are not pins are skipped.
  explicit ServerPins(std::filesystem::path file = {});

  /// Compares `key` (32 bytes) with the pin of `server`, pinning it at first sight.
  PinCheck check(const std::string& server, std::span<const std::uint8_t> key);
  /// The key pinned for `server`, if any.
  const std::array<std::uint8_t, protocol::kPublicKeyBytes>* pinned(
      const std::string& server) const;
  /// Forgets the pin of `server` (rewriting the file); false when none was pinned.
  bool forget(const std::string& server);
  /// Why the file could not be read or written last, or empty.
  const std::string& fileProblem() const { return file_problem_; }

 private:
  void load();
  void append(const std::string& server, std::span<const std::uint8_t> key);
  void rewrite();

  std::filesystem::path file_;
  std::map<std::string, std::array<std::uint8_t, protocol::kPublicKeyBytes>> pins_;
  std::string file_problem_;
};

}  // namespace pool::client
