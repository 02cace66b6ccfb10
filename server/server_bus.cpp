// Creating the server's topics, readers, writers and waitset.
#include "server_bus.h"

namespace pool::server {

ServerBus::ServerBus(std::uint32_t domain)
    : ProtocolTopics(domain),
      join_requests(participant, join_request_topic, net::qos::joinRequest()),
      commands(participant, command_topic, net::qos::command()),
      match_info(participant, match_info_topic, net::qos::lobby()),
      join_replies(participant, join_reply_topic, net::qos::joinReply()),
      results(participant, result_topic, net::qos::result()),
      snapshots(participant, snapshot_topic, net::qos::snapshot()),
      states(participant, state_topic, net::qos::state()),
      waitset(participant) {
  waitset.attachData(join_requests, kJoinTag);
  waitset.attachData(commands, kCommandTag);
}

}  // namespace pool::server
