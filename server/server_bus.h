// The server's DDS endpoints: one participant, the readers of requests and the writers of state.
#pragma once

#include <cstdint>

#include "net/messages.h"
#include "net/participant.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/topic.h"
#include "net/waitset.h"
#include "net/writer.h"

namespace pool::server {

/// Every topic of pool.idl as the server uses it, with docs/PROTOCOL.md's QoS (net's profiles).
/// Members are built in declaration order and destroyed in reverse, the participant last.
struct ServerBus : net::ProtocolTopics {
  /// Joins `domain` (its configuration from CYCLONEDDS_URI). Throws net::DdsError on failure.
  explicit ServerBus(std::uint32_t domain);

  net::Reader<pool_JoinRequest> join_requests;
  net::Reader<pool_ShotCommand> commands;
  net::Writer<pool_MatchInfo> match_info;
  net::Writer<pool_JoinReply> join_replies;
  net::Writer<pool_ShotResult> results;
  net::Writer<pool_TableSnapshot> snapshots;
  net::Writer<pool_MatchState> states;

  net::WaitSet waitset;  ///< wakes on join requests and commands (data and writer-gone notices)
};

/// Tags of the waitset's conditions.
enum BusTag : std::int64_t { kJoinTag = 1, kCommandTag = 2 };

}  // namespace pool::server
