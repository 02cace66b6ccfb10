// Looks for another server already live on the domain under a server id, before and while this
// one serves under it: the lobby entries of that id, and the answer of a server with our key to
// a challenge only a live one can answer.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "protocol/key_pair.h"

namespace pool::net {

/// What the probe saw of `server_id`'s lobby entries on the domain.
struct ServerSighting {
  bool seen = false;            ///< some lobby entry of that server id arrived
  bool ours = false;            ///< one of them verified with our own key
  bool strange = false;         ///< one of them did not (unsigned, forged, or another key's)
  std::string match;            ///< one of the matches listed (the first strange one's, if any)
  std::string key_fingerprint;  ///< the key the first strange one carried ("(none)": unsigned)
  std::string problem;          ///< why a strange one did not verify (empty when it did)
};

/// A participant of its own with a lobby reader, a join-request writer and a join-reply reader.
/// Throws DdsError from the constructor only.
///
/// A lobby entry proves nothing about now: anyone can write one under any server id (unsigned,
/// or signed by a key of their own), and a genuine one can be captured and written again long
/// after its server is gone. What proves that a server holding our key is live is its answer to
/// a challenge: a spectate request under a client id made up for this probe (a nonce), for a
/// match no server has, whose signed reply must name that client id. Only a live process with
/// the key can sign it, and no earlier reply names the nonce.
class ServerIdProbe {
 public:
  explicit ServerIdProbe(std::uint32_t domain);
  ~ServerIdProbe();
  ServerIdProbe(const ServerIdProbe&) = delete;
  ServerIdProbe& operator=(const ServerIdProbe&) = delete;

  /// Reads the lobby for `window` and reports what of `server_id` arrived; `key` is ours.
  ServerSighting look(const std::string& server_id, const protocol::KeyPair& key,
                      std::chrono::milliseconds window);
  /// Sends the challenge (again): a spectate request of `server_id`'s match 0, which no server
  /// has (match numbers start at 1), under the probe's nonce.
  void challenge(const std::string& server_id);
  /// Whether a reply to the challenge arrived signed with `key` for `server_id`, written by a
  /// participant other than `own_participant` (this server's own, which answers it too).
  bool answered(const std::string& server_id, const protocol::KeyPair& key,
                const std::string& own_participant);

 private:
  struct Endpoints;
  std::unique_ptr<Endpoints> e_;
  std::string nonce_;
  std::uint32_t request_ = 0;
};

}  // namespace pool::net
