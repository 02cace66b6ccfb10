// The canonical encoding of a shot command and its Ed25519 signature.
#include "net/command_signature.h"

#include <sodium.h>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <string_view>

#include "net/messages.h"
#include "net/sodium_init.h"

namespace pool::net {

namespace {

constexpr std::string_view kMagic = "POOL-SHOT";
constexpr std::size_t kMatchField = 40;
constexpr std::size_t kPocketField = 32;

/// Appends fixed-size little-endian fields to a SignedBytes buffer.
class Encoder {
 public:
  explicit Encoder(SignedBytes& out) : out_(out) {}

  void bytes(const void* data, std::size_t n) {
    std::memcpy(out_.data() + at_, data, n);
    at_ += n;
  }
  template <class T>
  void integer(T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      out_[at_++] = static_cast<std::uint8_t>(static_cast<std::uint64_t>(value) >> (8 * i));
    }
  }
  void number(double value) { integer(std::bit_cast<std::uint64_t>(value)); }
  /// A length byte, then the text zero-padded (or cut) to `field` bytes.
  void text(std::string_view value, std::size_t field) {
    const std::size_t n = std::min(value.size(), field);
    integer(static_cast<std::uint8_t>(n));
    bytes(value.data(), n);
    at_ += field - n;  // the buffer starts zeroed
  }
  std::size_t size() const { return at_; }

 private:
  SignedBytes& out_;
  std::size_t at_ = 0;
};

}  // namespace

SignedBytes signedBytes(const ShotRequest& c) {
  SignedBytes out{};
  Encoder e(out);
  e.bytes(kMagic.data(), kMagic.size());
  e.integer(kSignedLayoutVersion);
  e.integer(static_cast<std::uint32_t>(kProtocolVersion));
  e.text(c.match, kMatchField);
  e.integer(static_cast<std::int32_t>(c.seat));
  e.integer(c.seat_token);
  e.integer(c.seq);
  e.number(c.cue.yaw);
  e.number(c.cue.tip_side);
  e.number(c.cue.tip_height);
  e.number(c.cue.elevation);
  e.number(c.cue.speed);
  e.integer(static_cast<std::uint8_t>(c.cue.speed_is_ball));
  e.integer(static_cast<std::int32_t>(c.called_ball.value_or(-1)));
  e.text(c.called_pocket, kPocketField);
  e.integer(static_cast<std::uint8_t>(c.safety));
  e.integer(static_cast<std::uint8_t>(c.cue_ball_at.has_value()));
  e.number(c.cue_ball_at ? c.cue_ball_at->x() : 0.0);
  e.number(c.cue_ball_at ? c.cue_ball_at->y() : 0.0);
  e.integer(static_cast<std::uint8_t>(c.option));
  assert(e.size() == out.size());
  return out;
}

void signCommand(ShotRequest& command, const KeyPair& key) {
  initSodium();
  const SignedBytes message = signedBytes(command);
  command.signature.assign(kSignatureBytes, 0);
  crypto_sign_detached(command.signature.data(), nullptr, message.data(), message.size(),
                       key.secret_key.data());
}

SignatureCheck verifyCommand(const ShotRequest& command, std::span<const std::uint8_t> public_key) {
  if (command.signature.empty()) return SignatureCheck::Unsigned;
  if (command.signature.size() != kSignatureBytes || public_key.size() != kPublicKeyBytes) {
    return SignatureCheck::BadSignature;
  }
  initSodium();
  const SignedBytes message = signedBytes(command);
  const bool ok = crypto_sign_verify_detached(command.signature.data(), message.data(),
                                              message.size(), public_key.data()) == 0;
  return ok ? SignatureCheck::Valid : SignatureCheck::BadSignature;
}

}  // namespace pool::net
