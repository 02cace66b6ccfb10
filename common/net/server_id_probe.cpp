// The server-id probe: a lobby reader read for a while, and a challenge that only a live server
// holding our key can answer.
#include "net/server_id_probe.h"

#include <dds/dds.h>

#include <algorithm>
#include <array>
#include <random>

#include "core/hex.h"
#include "net/participant.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "protocol/protocol_version.h"

namespace pool::net {

struct ServerIdProbe::Endpoints : ProtocolTopics {
  explicit Endpoints(std::uint32_t domain)
      : ProtocolTopics(domain),
        lobby(participant, match_info_topic, qos::lobby()),
        requests(participant, join_request_topic, qos::joinRequest()),
        replies(participant, join_reply_topic, qos::joinReply()),
        waitset(participant) {
    waitset.attachData(lobby, 1);
  }

  Reader<pool_MatchInfo> lobby;
  Writer<pool_JoinRequest> requests;
  Reader<pool_JoinReply> replies;
  WaitSet waitset;
};

namespace {

bool sameKey(const protocol::SealedSample& sealed, const protocol::KeyPair& key) {
  return std::equal(sealed.server_key.begin(), sealed.server_key.end(), key.public_key.begin(),
                    key.public_key.end());
}

}  // namespace

ServerIdProbe::ServerIdProbe(std::uint32_t domain) : e_(std::make_unique<Endpoints>(domain)) {
  std::random_device random;
  std::array<std::uint8_t, 8> bytes{};
  for (auto& b : bytes) b = static_cast<std::uint8_t>(random());
  nonce_ = "id-probe-" + hexOf(bytes);
}

ServerIdProbe::~ServerIdProbe() = default;

ServerSighting ServerIdProbe::look(const std::string& server_id, const protocol::KeyPair& key,
                                   std::chrono::milliseconds window) {
  ServerSighting out;
  const auto deadline = std::chrono::steady_clock::now() + window;
  for (;;) {
    for (auto& sample : e_->lobby.take()) {
      if (textOf(sample->server) != server_id) continue;
      const auto sealed = sealedOf(*sample);
      out.seen = true;
      const auto seal = protocol::checkSeal(sealed);
      if (seal && sameKey(sealed, key)) {
        if (!out.strange) out.match = sealed.match;
        out.ours = true;
        continue;
      }
      if (!out.strange) {
        out.match = sealed.match;
        out.key_fingerprint =
            sealed.server_key.empty() ? "(none)" : protocol::fingerprint(sealed.server_key);
        out.problem = seal.error();
      }
      out.strange = true;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) break;
    e_->waitset.wait(
        std::min<std::chrono::nanoseconds>(deadline - now, std::chrono::milliseconds(50)));
  }
  return out;
}

void ServerIdProbe::challenge(const std::string& server_id) {
  pool_JoinRequest r{};
  setText(r.client, nonce_);
  r.request = ++request_;
  r.protocol_version = protocol::kProtocolVersion;
  setText(r.match, server_id + "-0");
  r.action = pool_JOIN_SPECTATE;
  r.seat = -1;
  (void)e_->requests.write(r);  // best effort: the next challenge goes out a second later
}

bool ServerIdProbe::answered(const std::string& server_id, const protocol::KeyPair& key,
                             const std::string& own_participant) {
  bool live = false;
  for (auto& sample : e_->replies.take()) {
    if (textOf(sample->client) != nonce_ || textOf(sample->server) != server_id) continue;
    const auto sealed = sealedOf(*sample);
    if (!protocol::checkSeal(sealed) || !sameKey(sealed, key)) continue;
    const std::string writer = e_->replies.participantOf(sample.meta().publication_handle);
    if (!writer.empty() && writer != own_participant) live = true;
  }
  return live;
}

}  // namespace pool::net
