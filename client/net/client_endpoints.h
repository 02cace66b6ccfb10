// The client's DDS endpoints: one participant, the protocol's topics, a reader or writer for each
// direction, and a waitset over the readers. The only client file that owns DDS entities.
#pragma once

#include <chrono>
#include <cstdint>

#include "net/messages.h"
#include "net/participant.h"
#include "net/protocol_topics.h"
#include "net/reader.h"
#include "net/topic.h"
#include "net/waitset.h"
#include "net/writer.h"

namespace pool::client {

/// How deep the client's readers keep results and states per instance, so that a slow poll does
/// not lose the acceptance of a shot behind its final report, or a state behind the next one.
inline constexpr std::uint32_t kReaderDepth = 16;
/// Snapshots kept per match between polls: an unpaced server (--fast) sends a shot's frames in a
/// burst, and a spectator counting them should see most of them.
inline constexpr std::uint32_t kSnapshotDepth = 512;

/// Every endpoint a player or spectator needs. Throws net::DdsError when DDS refuses one.
struct ClientEndpoints : net::ProtocolTopics {
  explicit ClientEndpoints(std::uint32_t domain);

  net::Reader<pool_MatchInfo> match_info;
  net::Reader<pool_JoinReply> join_replies;
  net::Reader<pool_ShotResult> results;
  net::Reader<pool_TableSnapshot> snapshots;
  net::Reader<pool_MatchState> states;
  /// Kept for the whole session: its liveliness tells the server we are still here.
  net::Writer<pool_JoinRequest> join_requests;
  net::Writer<pool_ShotCommand> commands;

  net::WaitSet waitset;

  /// Blocks until some reader has data or `timeout` passes.
  void wait(std::chrono::nanoseconds timeout) const { waitset.wait(timeout); }
};

}  // namespace pool::client
