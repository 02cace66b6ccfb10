// The server-id probe: a lobby reader read for a while, the entries of one server id checked.
#include "net/server_id_probe.h"

#include <dds/dds.h>

#include <algorithm>

#include "net/participant.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/topic.h"
#include "net/waitset.h"
#include "net/wire_fields.h"

namespace pool::net {

struct ServerIdProbe::Endpoints {
  explicit Endpoints(std::uint32_t domain)
      : participant(domain),
        topic(participant),
        reader(participant, topic, qos::lobby()),
        waitset(participant) {
    waitset.attachData(reader, 1);
  }

  Participant participant;
  Topic<pool_MatchInfo> topic;
  Reader<pool_MatchInfo> reader;
  WaitSet waitset;
};

ServerIdProbe::ServerIdProbe(std::uint32_t domain) : e_(std::make_unique<Endpoints>(domain)) {}

ServerIdProbe::~ServerIdProbe() = default;

ServerSighting ServerIdProbe::look(const std::string& server_id, const protocol::KeyPair& key,
                                   std::chrono::milliseconds window) {
  ServerSighting out;
  out.same_key = true;
  const auto deadline = std::chrono::steady_clock::now() + window;
  for (;;) {
    for (auto& sample : e_->reader.take()) {
      if (textOf(sample->server) != server_id) continue;
      const auto sealed = sealedOf(*sample);
      if (!out.seen) {
        out.match = sealed.match;
        out.key_fingerprint = protocol::fingerprint(sealed.server_key);
      }
      out.seen = true;
      writers_.push_back(sample.meta().publication_handle);
      const auto problem = protocol::sealProblem(sealed);
      const bool ours = std::equal(sealed.server_key.begin(), sealed.server_key.end(),
                                   key.public_key.begin(), key.public_key.end());
      if (!problem.empty() && out.problem.empty()) out.problem = problem;
      if (!problem.empty() || !ours) out.same_key = false;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) break;
    e_->waitset.wait(
        std::min<std::chrono::nanoseconds>(deadline - now, std::chrono::milliseconds(50)));
  }
  if (!out.seen) out.same_key = false;
  return out;
}

bool ServerIdProbe::stillLive() const {
  if (writers_.empty()) return false;
  std::vector<dds_instance_handle_t> matched(64);
  const dds_return_t n =
      dds_get_matched_publications(e_->reader.handle(), matched.data(), matched.size());
  if (n < 0) return false;
  matched.resize(std::min(static_cast<std::size_t>(n), matched.size()));
  return std::any_of(writers_.begin(), writers_.end(), [&](std::uint64_t w) {
    return std::find(matched.begin(), matched.end(), w) != matched.end();
  });
}

}  // namespace pool::net
