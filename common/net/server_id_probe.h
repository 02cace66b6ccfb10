// Looks for another server already live on the domain under a server id, before this one serves
// under it: the lobby entries it publishes, the key they are signed with, and whether the writers
// that published them are still there.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "protocol/key_pair.h"

namespace pool::net {

/// What the probe saw of `server_id` on the domain.
struct ServerSighting {
  bool seen = false;            ///< some lobby entry of that server id arrived
  bool same_key = false;        ///< every one of them verified with our own key
  std::string match;            ///< one of the matches listed
  std::string key_fingerprint;  ///< the key the first one carried ("(none)" when unsigned)
  std::string problem;          ///< why a seen entry did not verify (empty when they all did)
};

/// A participant of its own with a lobby reader. Throws DdsError from the constructor only.
class ServerIdProbe {
 public:
  explicit ServerIdProbe(std::uint32_t domain);
  ~ServerIdProbe();
  ServerIdProbe(const ServerIdProbe&) = delete;
  ServerIdProbe& operator=(const ServerIdProbe&) = delete;

  /// Reads the lobby for `window` and reports what of `server_id` arrived; `key` is ours.
  ServerSighting look(const std::string& server_id, const protocol::KeyPair& key,
                      std::chrono::milliseconds window);
  /// True while a writer that published one of those entries is still matched with the probe
  /// (a process that crashed is unmatched when its lease runs out).
  bool stillLive() const;

 private:
  struct Endpoints;
  std::unique_ptr<Endpoints> e_;
  std::vector<std::uint64_t> writers_;  ///< publication handles of the entries seen
};

}  // namespace pool::net
