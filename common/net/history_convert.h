// Replays on the wire: history requests and stored shots to and from their samples, with the
// bounds of their fields checked on the way in.
#pragma once

#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"
#include "protocol/history.h"

namespace pool::net {

Sample<pool_HistoryRequest> toWire(const protocol::HistoryRequest& request);
/// Reads a request: texts within their bounds, a 32-byte key, at most a 64-byte signature (the
/// request's own checks, protocol::checkHistoryRequest, are the server's to make).
Result<protocol::HistoryRequest> fromWire(const pool_HistoryRequest& request);

/// `shot` as a sample (balls past MAX_BALLS and events past MAX_EVENTS are cut).
Sample<pool_HistoryShot> toWire(const protocol::HistoryShot& shot);
/// Reads a stored shot: texts within their bounds, a known game, every ball and event readable.
Result<protocol::HistoryShot> fromWire(const pool_HistoryShot& shot);

}  // namespace pool::net
