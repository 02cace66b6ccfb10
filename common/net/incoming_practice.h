// A practice command as the server reads it off the wire, in domain terms: the request, or why
// its fields cannot be read.
#pragma once

#include "net/incoming_command.h"
#include "protocol/practice_request.h"

namespace pool::net {

/// A practice command off the wire, read like a shot command.
using IncomingPractice = IncomingSigned<protocol::PracticeRequest>;

}  // namespace pool::net
