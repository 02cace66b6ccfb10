// Creating the participant and the protocol's topics.
#include "net/protocol_topics.h"

namespace pool::net {

ProtocolTopics::ProtocolTopics(std::uint32_t domain)
    : participant(domain),
      match_info_topic(participant),
      join_request_topic(participant),
      join_reply_topic(participant),
      command_topic(participant),
      result_topic(participant),
      snapshot_topic(participant),
      state_topic(participant),
      practice_topic(participant),
      aim_command_topic(participant),
      cue_aim_topic(participant),
      player_stats_topic(participant),
      history_request_topic(participant),
      history_shot_topic(participant),
      tournament_topic(participant) {}

}  // namespace pool::net
