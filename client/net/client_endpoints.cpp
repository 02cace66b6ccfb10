// Creating the client's participant, topics, readers, writers and waitset.
#include "client/net/client_endpoints.h"

#include "net/qos_profiles.h"

namespace pool::client {
namespace {

net::QosProfile deeper(net::QosProfile profile, std::uint32_t depth = kReaderDepth) {
  profile.history_depth = depth;
  return profile;
}

enum WaitTag : std::int64_t { kLobby = 1, kReplies, kResults, kSnapshots, kStates };

}  // namespace

ClientEndpoints::ClientEndpoints(std::uint32_t domain)
    : ProtocolTopics(domain),
      match_info(participant, match_info_topic, net::qos::lobby()),
      join_replies(participant, join_reply_topic, net::qos::joinReply()),
      results(participant, result_topic, deeper(net::qos::result())),
      snapshots(participant, snapshot_topic, deeper(net::qos::snapshot(), kSnapshotDepth)),
      states(participant, state_topic, deeper(net::qos::state())),
      join_requests(participant, join_request_topic, net::qos::joinRequest()),
      commands(participant, command_topic, net::qos::command()),
      waitset(participant) {
  waitset.attachData(match_info, kLobby);
  waitset.attachData(join_replies, kReplies);
  waitset.attachData(results, kResults);
  waitset.attachData(snapshots, kSnapshots);
  waitset.attachData(states, kStates);
}

}  // namespace pool::client
