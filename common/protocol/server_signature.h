// The server's signature of what it publishes: the signed bytes of a published sample, the check
// of a received one against the key it carries, key fingerprints, and whose a match id is.
#pragma once

#include "core/check.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/envelope.h"
#include "protocol/key_pair.h"

namespace pool::protocol {

/// Which published message a server signature is for; part of the signed bytes, so a signature
/// made for one kind never verifies as another.
enum class PublishedKind : std::uint8_t {
  MatchInfo = 1,
  JoinReply = 2,
  MatchState = 3,
  ShotResult = 4,
  TableSnapshot = 5,
  CueAim = 6,          ///< the shooter's aim, relayed
  PlayerStats = 7,     ///< a player's statistics and rating (since protocol version 9)
  HistoryShot = 8,     ///< a stored shot, for a replay (since protocol version 10)
  TournamentInfo = 9,  ///< a tournament and its bracket (since protocol version 10)
};

const char* toString(PublishedKind kind);

/// One received sample as its signature sees it: who it speaks for, the key and signature it
/// carries, and its encoding with the signature left empty (filled in by the wire module).
struct SealedSample {
  PublishedKind kind = PublishedKind::MatchInfo;
  std::string server;  ///< the server id it speaks for (MatchInfo, JoinReply: its field; the
                       ///< others: the prefix of their match id)
  std::string match;   ///< the match it is about (empty when none)
  std::uint32_t protocol_version = 0;  ///< MatchInfo's; 0 for the other kinds
  std::vector<std::uint8_t> server_key;
  std::vector<std::uint8_t> signature;
  std::vector<std::uint8_t> body;  ///< the sample's encoding, signature empty
};

/// The bytes a server signs for a sample of `kind` whose encoding is `body`:
///   "POOL-SRV" (8) | protocol version u32 | kind u8 | body.
std::vector<std::uint8_t> serverSignedBytes(PublishedKind kind, std::span<const std::uint8_t> body);

/// The server's signature (64 bytes) of a sample of `kind` encoded as `body`.
std::vector<std::uint8_t> signPublished(PublishedKind kind, std::span<const std::uint8_t> body,
                                        const KeyPair& key);

/// Checks `sample`'s signature against the key it carries (which says nothing of whether that key
/// is the server's: the pins decide that).
SignatureCheck verifyPublished(const SealedSample& sample);

/// A short, stable name of a public key for people to compare: the first 16 bytes of its BLAKE2b
/// hash in hex, in groups of four ("3f2a:9c01:…", 39 characters). "(none)" for an empty key.
std::string fingerprint(std::span<const std::uint8_t> public_key);

/// The longest server id: "<id>-<n>" must fit a match id's 39 bytes for any n a server reaches.
inline constexpr std::size_t kMaxServerIdLength = 24;

/// True for a server id a server may use: 1-kMaxServerIdLength letters, digits, '.', '_' or '-'
/// (nothing that could break a log line or a file of pins).
bool validServerId(std::string_view id);

/// The server id of a match id "<server id>-<n>": everything before the last '-' (empty when
/// there is none).
std::string serverOfMatch(std::string_view match);

/// Passes a received sample whose signature verifies against the key it carries; refuses one
/// of another protocol version (MatchInfo tells: "protocol_mismatch"), with no signature
/// ("unsigned"), or with a signature that does not verify ("bad_signature").
Check<> checkSeal(const SealedSample& sample);

}  // namespace pool::protocol
