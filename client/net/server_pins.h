// The server keys a client trusts: each server id's Ed25519 key, pinned the first time a sample
// signed by it arrives, kept in a file (owner-only) or in memory, forgotten on an operator's word;
// past the pins kept for good, new ones wait on probation, where a flood of made-up ids evicts
// only its own kind.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <span>
#include <string>
#include <utility>

#include "protocol/key_pair.h"

namespace pool::client {

/// `$XDG_CONFIG_HOME/pool/servers`, or `~/.config/pool/servers`; empty when neither is set.
std::filesystem::path defaultServerPinFile();

/// How a server's key compares with its pin.
enum class PinCheck : std::uint8_t {
  FirstSight,  ///< nothing was pinned for that server id: now this key is
  Same,        ///< the pinned key
  Changed,     ///< another key is pinned for that server id
  Refused      ///< not a server id a server may use
};

/// Server id -> pinned key. With a file, pins are read from it at construction and every pin kept
/// for good is added to it (one line "<server id> <key in hex>", the file owner-only); without one
/// they last as long as the object. The first kMaxPins pins (the file's first) are kept for good:
/// nothing evicts them. Past them a new server id is pinned on probation, in memory only: at most
/// kMaxProbation such pins, the one whose key signed last longest ago evicted for a new one (a
/// flood of made-up ids churns only the probation pins, and a new real server is still pinned,
/// again at its next sample should the flood have evicted it). A probation pin is kept for good
/// once there is room (after a forget).
class ServerPins {
 public:
  static constexpr std::size_t kMaxPins = 1024;
  static constexpr std::size_t kMaxProbation = 256;

  /// Pins kept in `file` (empty: in memory only). Lines that are not pins are skipped.
  explicit ServerPins(std::filesystem::path file = {});

  /// Compares `key` (32 bytes) with the pin of `server`, pinning it at first sight.
  PinCheck check(const std::string& server, std::span<const std::uint8_t> key);
  /// The key pinned for `server`, if any.
  const std::array<std::uint8_t, protocol::kPublicKeyBytes>* pinned(
      const std::string& server) const;
  /// Forgets the pin of `server` (rewriting the file); false when none was pinned.
  bool forget(const std::string& server);
  /// Whether the pin of `server` is on probation (evictable by a new server id).
  bool onProbation(const std::string& server) const;
  /// Probation pins evicted so far.
  std::uint64_t evicted() const { return evicted_; }
  /// Why the file could not be read or written last, or empty.
  const std::string& fileProblem() const { return file_problem_; }

 private:
  void load();
  void append(const std::string& server, std::span<const std::uint8_t> key);
  void rewrite();

  /// Moves a probation pin to the pins kept for good when there is room; false when none.
  bool settle(const std::string& server);

  struct Probation {
    std::array<std::uint8_t, protocol::kPublicKeyBytes> key;
    std::uint64_t last = 0;  ///< the check that last found its key (a counter)
  };

  std::filesystem::path file_;
  std::map<std::string, std::array<std::uint8_t, protocol::kPublicKeyBytes>> pins_;  ///< for good
  std::map<std::string, Probation> probation_;
  std::set<std::pair<std::uint64_t, std::string>> probation_order_;  ///< (last, server)
  std::uint64_t checks_ = 0;
  std::uint64_t evicted_ = 0;
  std::string file_problem_;
};

}  // namespace pool::client
