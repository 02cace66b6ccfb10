// The canonical encoding of a published sample and its reading as a protocol::SealedSample.
#include "net/server_seal.h"

#include <dds/ddsi/ddsi_cdrstream.h>

namespace pool::net {

namespace detail {

namespace {
constexpr std::uint32_t kXcdr2 = 2;  ///< the encoding Cyclone uses for @appendable types
}  // namespace

std::vector<std::uint8_t> encodeCanonical(const void* sample,
                                          const dds_topic_descriptor_t* descriptor) {
  dds_ostreamLE_t os;
  dds_ostreamLE_init(&os, 0, kXcdr2);
  dds_stream_writeLE(&os, static_cast<const char*>(sample), descriptor->m_ops);
  std::vector<std::uint8_t> bytes(os.x.m_buffer, os.x.m_buffer + os.x.m_index);
  dds_ostreamLE_fini(&os);
  return bytes;
}

}  // namespace detail

namespace {

template <class T>
protocol::SealedSample common(const T& sample, std::string server, std::string match) {
  protocol::SealedSample out;
  out.kind = publishedKindOf<T>();
  out.server = std::move(server);
  out.match = std::move(match);
  const auto key = elementsOf(sample.server_key);
  out.server_key.assign(key.begin(), key.end());
  const auto signature = elementsOf(sample.signature);
  out.signature.assign(signature.begin(), signature.end());
  out.body = sealedBody(sample);
  return out;
}

template <class T>
protocol::SealedSample ofMatch(const T& sample) {
  std::string match(textOf(sample.match));
  std::string server = protocol::serverOfMatch(match);
  return common(sample, std::move(server), std::move(match));
}

}  // namespace

protocol::SealedSample sealedOf(const pool_MatchInfo& sample) {
  auto out = common(sample, std::string(textOf(sample.server)), std::string(textOf(sample.match)));
  out.protocol_version = sample.protocol_version;
  return out;
}

protocol::SealedSample sealedOf(const pool_JoinReply& sample) {
  return common(sample, std::string(textOf(sample.server)), std::string(textOf(sample.match)));
}

protocol::SealedSample sealedOf(const pool_MatchState& sample) {
  return ofMatch(sample);
}

protocol::SealedSample sealedOf(const pool_ShotResult& sample) {
  return ofMatch(sample);
}

protocol::SealedSample sealedOf(const pool_TableSnapshot& sample) {
  return ofMatch(sample);
}

protocol::SealedSample sealedOf(const pool_CueAim& sample) {
  return ofMatch(sample);
}

protocol::SealedSample sealedOf(const pool_PlayerStats& sample) {
  return common(sample, std::string(textOf(sample.server)), {});
}

protocol::SealedSample sealedOf(const pool_HistoryShot& sample) {
  return ofMatch(sample);
}

protocol::SealedSample sealedOf(const pool_TournamentInfo& sample) {
  return common(sample, std::string(textOf(sample.server)), {});
}

}  // namespace pool::net
