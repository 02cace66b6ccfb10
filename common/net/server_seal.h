// The server's signature on the wire: a published sample encoded canonically (its whole CDR with
// the signature left empty), sealed with the server's key before it is written, and read back
// as a protocol::SealedSample for the clients' checks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "net/messages.h"
#include "net/wire_fields.h"
#include "protocol/key_pair.h"
#include "protocol/server_signature.h"

namespace pool::net {

namespace detail {
/// `sample`'s little-endian XCDR2 encoding by `descriptor` (the same bytes on every host).
std::vector<std::uint8_t> encodeCanonical(const void* sample,
                                          const dds_topic_descriptor_t* descriptor);
}  // namespace detail

/// The published kind of each server-signed wire type.
template <class T>
constexpr protocol::PublishedKind publishedKindOf();
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_MatchInfo>() {
  return protocol::PublishedKind::MatchInfo;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_JoinReply>() {
  return protocol::PublishedKind::JoinReply;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_MatchState>() {
  return protocol::PublishedKind::MatchState;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_ShotResult>() {
  return protocol::PublishedKind::ShotResult;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_TableSnapshot>() {
  return protocol::PublishedKind::TableSnapshot;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_CueAim>() {
  return protocol::PublishedKind::CueAim;
}

template <>
constexpr protocol::PublishedKind publishedKindOf<pool_PlayerStats>() {
  return protocol::PublishedKind::PlayerStats;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_HistoryShot>() {
  return protocol::PublishedKind::HistoryShot;
}
template <>
constexpr protocol::PublishedKind publishedKindOf<pool_TournamentInfo>() {
  return protocol::PublishedKind::TournamentInfo;
}

/// What the server's signature covers: every field of `sample`, in its wire encoding, with the
/// signature empty. Generic over the type, so fields added to a message later are covered too.
template <class T>
std::vector<std::uint8_t> sealedBody(const T& sample) {
  T unsigned_copy = sample;  // a shallow copy of the C struct: read, never freed
  unsigned_copy.signature._length = 0;
  unsigned_copy.signature._maximum = 0;
  unsigned_copy.signature._buffer = nullptr;
  unsigned_copy.signature._release = false;
  return detail::encodeCanonical(&unsigned_copy, MessageTraits<T>::descriptor());
}

/// Puts `key`'s public half and its signature of the sample into `sample`.
template <class T>
void seal(T& sample, const protocol::KeyPair& key) {
  setBytes(sample.server_key, key.public_key, protocol::kPublicKeyBytes);
  resizeSequence(sample.signature, 0);
  const auto signature = protocol::signPublished(publishedKindOf<T>(), sealedBody(sample), key);
  setBytes(sample.signature, signature, protocol::kSignatureBytes);
}

/// `sample` as its signature sees it, ready for protocol::checkSeal and the clients' pins.
protocol::SealedSample sealedOf(const pool_MatchInfo& sample);
protocol::SealedSample sealedOf(const pool_JoinReply& sample);
protocol::SealedSample sealedOf(const pool_MatchState& sample);
protocol::SealedSample sealedOf(const pool_ShotResult& sample);
protocol::SealedSample sealedOf(const pool_TableSnapshot& sample);
protocol::SealedSample sealedOf(const pool_CueAim& sample);
protocol::SealedSample sealedOf(const pool_PlayerStats& sample);
protocol::SealedSample sealedOf(const pool_HistoryShot& sample);
protocol::SealedSample sealedOf(const pool_TournamentInfo& sample);

}  // namespace pool::net
