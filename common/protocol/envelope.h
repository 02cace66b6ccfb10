// The one signed envelope of every player message (shot, seat request, aim, practice, history): a
// fixed header naming the message kind, match, seat holding and sequence number, then the kind's
// fields.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "protocol/key_pair.h"

namespace pool::protocol {

/// The version of the envelope's byte layout; raised whenever any message's layout changes.
inline constexpr std::uint32_t kEnvelopeLayoutVersion = 3;

/// Bytes of the header every signed message starts with.
inline constexpr std::size_t kEnvelopeHeaderBytes = 8 + 4 + 4 + 1 + 41 + 4 + 8 + 4;

/// Which message an envelope carries; part of the signed bytes, so a signature made for one kind
/// of message never verifies as another.
enum class MessageTag : std::uint8_t {
  Shot = 1,         ///< a ShotCommand
  SeatRequest = 2,  ///< a JoinRequest that changes a seat (take, rejoin, leave, rematch, concede)
  Aim = 3,          ///< the shooter's cue while aiming
  Practice = 4,     ///< a practice-table command
  History = 5,      ///< a request for a match's stored shots (protocol/history.h)
};

/// What every signed message names: its kind, the match, the seat holding and a sequence number.
struct EnvelopeHeader {
  MessageTag tag = MessageTag::Shot;
  std::string_view match;   ///< match id (cut to 40 bytes)
  int seat = -1;            ///< 0 or 1; -1 where the request names no seat (any free one)
  std::uint64_t token = 0;  ///< the seat holding's token (public: it names a holding)
  std::uint32_t seq = 0;    ///< per key, strictly increasing
};

/// Builds the signed bytes of one message, all integers little-endian, doubles as their IEEE-754
/// bits, text as a length byte and the text zero-padded to its field:
///   "POOL-MSG" (8) | layout version u32 | protocol version u32 | tag u8 |
///   match length u8 + 40 | seat i32 | token u64 | seq u32 | the message's fields.
class SignedEncoder {
 public:
  explicit SignedEncoder(const EnvelopeHeader& header);

  void u8(std::uint8_t value) { integer(value); }
  void i32(std::int32_t value) { integer(value); }
  void u32(std::uint32_t value) { integer(value); }
  void u64(std::uint64_t value) { integer(value); }
  void f64(double value);
  /// A length byte, then the text zero-padded (or cut) to `field` bytes.
  void text(std::string_view value, std::size_t field);
  /// Exactly `field` bytes: `data` zero-padded (or cut).
  void bytes(std::span<const std::uint8_t> data, std::size_t field);

  const std::vector<std::uint8_t>& message() const { return out_; }

 private:
  template <class T>
  void integer(T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      out_.push_back(static_cast<std::uint8_t>(static_cast<std::uint64_t>(value) >> (8 * i)));
    }
  }

  std::vector<std::uint8_t> out_;
};

/// How a message's signature fares against a public key.
enum class SignatureCheck : std::uint8_t {
  Valid,
  Unsigned,      ///< no signature at all
  BadSignature,  ///< not 64 bytes, or not the key's signature of these bytes
};

/// `key`'s Ed25519 signature (64 bytes) of `message`.
std::vector<std::uint8_t> signMessage(std::span<const std::uint8_t> message, const KeyPair& key);

/// Checks `signature` over `message` against `public_key` (32 bytes; any other length fails).
SignatureCheck verifyMessage(std::span<const std::uint8_t> message,
                             std::span<const std::uint8_t> signature,
                             std::span<const std::uint8_t> public_key);

}  // namespace pool::protocol
