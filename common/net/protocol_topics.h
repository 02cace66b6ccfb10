// One participant and every topic of pool.idl: what the server and each client open before their
// readers and writers.
#pragma once

#include <cstdint>

#include "net/messages.h"
#include "net/participant.h"
#include "net/topic.h"

namespace pool::net {

/// The participant on `domain` (configured by CYCLONEDDS_URI) and the protocol's fourteen topics.
/// Endpoint sets derive from it, so their readers and writers are destroyed before the topics
/// and the participant. Throws DdsError when DDS refuses one.
struct ProtocolTopics {
  explicit ProtocolTopics(std::uint32_t domain);

  Participant participant;
  Topic<pool_MatchInfo> match_info_topic;
  Topic<pool_JoinRequest> join_request_topic;
  Topic<pool_JoinReply> join_reply_topic;
  Topic<pool_ShotCommand> command_topic;
  Topic<pool_ShotResult> result_topic;
  Topic<pool_TableSnapshot> snapshot_topic;
  Topic<pool_MatchState> state_topic;
  Topic<pool_PracticeCommand> practice_topic;
  Topic<pool_AimCommand> aim_command_topic;          ///< player -> server
  Topic<pool_CueAim> cue_aim_topic;                  ///< per match, like snapshot_topic
  Topic<pool_PlayerStats> player_stats_topic;        ///< server -> all, like match_info_topic
  Topic<pool_HistoryRequest> history_request_topic;  ///< anyone -> server
  Topic<pool_HistoryShot> history_shot_topic;        ///< server -> all
  Topic<pool_TournamentInfo> tournament_topic;       ///< server -> all, like match_info_topic
};

}  // namespace pool::net
