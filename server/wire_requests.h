// Incoming requests from the wire, checked before the match logic sees them.
#pragma once

#include <string>

#include "core/result.h"
#include "match/join.h"
#include "match/match_types.h"
#include "net/messages.h"
#include "net/shot_command_check.h"
#include "protocol/shot_request.h"
#include "table/table_spec.h"

namespace pool::server {

/// A join request in domain terms; fails on an unknown action or unterminated text.
Result<JoinCommand> joinCommand(const pool_JoinRequest& request);

/// The reply refusing a request that joinCommand could not read (outcome JOIN_NOT_ALLOWED; its
/// action field says JOIN_SEAT, since the request's may be no enumerator).
pool_JoinReply unreadableJoinReply(const pool_JoinRequest& request, const std::string& reason,
                                   const std::string& server_id);

/// The wire limits of a command on `spec`'s table (speed, elevation, miscue, playing surface).
protocol::CommandLimits commandLimits(const table::TableSpec& spec);

/// A shot command that passed the wire checks, or the refusal to publish for it.
struct ReadCommand {
  protocol::ShotRequest request;  ///< meaningful when `refusal` is accepted()
  CommandAnswer refusal;          ///< reason None: the request goes on to its match
};

/// Checks `command`'s fields (net's validateShotCommand) and converts it; a failure becomes a
/// Malformed refusal (BadSignature for a bad signature field).
ReadCommand readCommand(const pool_ShotCommand& command, const protocol::CommandLimits& limits);

}  // namespace pool::server
