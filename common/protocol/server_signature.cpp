// Signing and checking what the server publishes, and the fingerprints of server keys.
#include "protocol/server_signature.h"

#include <sodium.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "core/text.h"
#include "protocol/protocol_version.h"
#include "protocol/sodium_init.h"

namespace pool::protocol {

namespace {

constexpr std::string_view kMagic = "POOL-SRV";
constexpr std::size_t kFingerprintBytes = 16;

}  // namespace

const char* toString(PublishedKind kind) {
  switch (kind) {
    case PublishedKind::MatchInfo:
      return "MatchInfo";
    case PublishedKind::JoinReply:
      return "JoinReply";
    case PublishedKind::MatchState:
      return "MatchState";
    case PublishedKind::ShotResult:
      return "ShotResult";
    case PublishedKind::TableSnapshot:
      return "TableSnapshot";
    case PublishedKind::CueAim:
      return "CueAim";
    case PublishedKind::PlayerStats:
      return "PlayerStats";
    case PublishedKind::HistoryShot:
      return "HistoryShot";
    case PublishedKind::TournamentInfo:
      return "TournamentInfo";
  }
  return "?";
}

std::vector<std::uint8_t> serverSignedBytes(PublishedKind kind,
                                            std::span<const std::uint8_t> body) {
  // Appended, not written by index: g++ 12 at -O3 misreads indexed writes into a fresh vector
  // as overflowing (-Wstringop-overflow).
  std::vector<std::uint8_t> out;
  out.reserve(kMagic.size() + 5 + body.size());
  for (const char c : kMagic) out.push_back(static_cast<std::uint8_t>(c));
  const auto version = static_cast<std::uint32_t>(kProtocolVersion);
  for (std::size_t i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(version >> (8 * i)));
  out.push_back(static_cast<std::uint8_t>(kind));
  out.insert(out.end(), body.begin(), body.end());
  return out;
}

std::vector<std::uint8_t> signPublished(PublishedKind kind, std::span<const std::uint8_t> body,
                                        const KeyPair& key) {
  return signMessage(serverSignedBytes(kind, body), key);
}

SignatureCheck verifyPublished(const SealedSample& sample) {
  return verifyMessage(serverSignedBytes(sample.kind, sample.body), sample.signature,
                       sample.server_key);
}

std::string fingerprint(std::span<const std::uint8_t> public_key) {
  if (public_key.empty()) return "(none)";
  initSodium();
  std::uint8_t hash[kFingerprintBytes];
  crypto_generichash(hash, sizeof hash, public_key.data(), public_key.size(), nullptr, 0);
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < kFingerprintBytes; ++i) {
    if (i > 0 && i % 2 == 0) out += ':';
    out += kHex[hash[i] >> 4];
    out += kHex[hash[i] & 15];
  }
  return out;
}

bool validServerId(std::string_view id) {
  return !id.empty() && id.size() <= kMaxServerIdLength &&
         std::all_of(id.begin(), id.end(), [](char ch) {
           return std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_' ||
                  ch == '-';
         });
}

std::string serverOfMatch(std::string_view match) {
  const auto dash = match.rfind('-');
  return dash == std::string_view::npos ? std::string() : std::string(match.substr(0, dash));
}

Check<> checkSeal(const SealedSample& sample) {
  const std::string what = std::string(toString(sample.kind)) +
                           (sample.match.empty() ? "" : " of " + escapedForLog(sample.match)) +
                           " from server '" + escapedForLog(sample.server) + "'";
  if (sample.kind == PublishedKind::MatchInfo && sample.protocol_version != kProtocolVersion) {
    return Check<>::refuse("protocol_mismatch", what + " dropped: it speaks protocol " +
                                                    std::to_string(sample.protocol_version) +
                                                    ", this program " +
                                                    std::to_string(kProtocolVersion));
  }
  switch (verifyPublished(sample)) {
    case SignatureCheck::Valid:
      return Check<>::pass();
    case SignatureCheck::Unsigned:
      return Check<>::refuse(
          "unsigned", what + " dropped: unsigned (a forgery, or a server older than protocol 4)");
    case SignatureCheck::BadSignature:
      break;
  }
  return Check<>::refuse(
      "bad_signature", what + " dropped: its signature does not verify with the key it carries (" +
                           fingerprint(sample.server_key) + ")");
}

}  // namespace pool::protocol
