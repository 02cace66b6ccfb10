// Practice commands on the wire: a PracticeRequest as a PracticeCommand sample, and a received
// sample read back with its fields checked.
#pragma once

#include "net/incoming_practice.h"
#include "net/messages.h"
#include "net/sample.h"
#include "protocol/command_limits.h"
#include "protocol/practice_request.h"

namespace pool::net {

/// `request` as a PracticeCommand sample (at most protocol::kPracticeMaxBalls balls, 22, and a
/// 64-byte signature are kept).
Sample<pool_PracticeCommand> toWire(const protocol::PracticeRequest& request);

/// Reads `command`: match id and seat, a known action, at most protocol::kPracticeMaxBalls balls,
/// then protocol::checkPracticeFields against `limits`' table size, then the signature's length.
IncomingPractice readPractice(const pool_PracticeCommand& command,
                              const protocol::CommandLimits& limits = {});

}  // namespace pool::net
