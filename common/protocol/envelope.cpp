// The signed envelope's header encoding and the Ed25519 signing and checking of its bytes.
#include "protocol/envelope.h"

#include <sodium.h>

#include <algorithm>
#include <bit>

#include "protocol/protocol_version.h"
#include "protocol/sodium_init.h"

namespace pool::protocol {

namespace {

constexpr std::string_view kMagic = "POOL-MSG";
constexpr std::size_t kMatchField = 40;

}  // namespace

SignedEncoder::SignedEncoder(const EnvelopeHeader& h) {
  out_.reserve(kEnvelopeHeaderBytes + 160);
  out_.insert(out_.end(), kMagic.begin(), kMagic.end());
  u32(kEnvelopeLayoutVersion);
  u32(static_cast<std::uint32_t>(kProtocolVersion));
  u8(static_cast<std::uint8_t>(h.tag));
  text(h.match, kMatchField);
  i32(static_cast<std::int32_t>(h.seat));
  u64(h.token);
  u32(h.seq);
}

void SignedEncoder::f64(double value) {
  integer(std::bit_cast<std::uint64_t>(value));
}

void SignedEncoder::text(std::string_view value, std::size_t field) {
  const std::size_t n = std::min(value.size(), field);
  u8(static_cast<std::uint8_t>(n));
  out_.insert(out_.end(), value.begin(), value.begin() + static_cast<std::ptrdiff_t>(n));
  out_.insert(out_.end(), field - n, 0);
}

void SignedEncoder::bytes(std::span<const std::uint8_t> data, std::size_t field) {
  const std::size_t n = std::min(data.size(), field);
  out_.insert(out_.end(), data.begin(), data.begin() + static_cast<std::ptrdiff_t>(n));
  out_.insert(out_.end(), field - n, 0);
}

std::vector<std::uint8_t> signMessage(std::span<const std::uint8_t> message, const KeyPair& key) {
  initSodium();
  std::vector<std::uint8_t> signature(kSignatureBytes, 0);
  crypto_sign_detached(signature.data(), nullptr, message.data(), message.size(),
                       key.secret_key.data());
  return signature;
}

SignatureCheck verifyMessage(std::span<const std::uint8_t> message,
                             std::span<const std::uint8_t> signature,
                             std::span<const std::uint8_t> public_key) {
  if (signature.empty()) return SignatureCheck::Unsigned;
  if (signature.size() != kSignatureBytes || public_key.size() != kPublicKeyBytes) {
    return SignatureCheck::BadSignature;
  }
  initSodium();
  const bool ok = crypto_sign_verify_detached(signature.data(), message.data(), message.size(),
                                              public_key.data()) == 0;
  return ok ? SignatureCheck::Valid : SignatureCheck::BadSignature;
}

}  // namespace pool::protocol
