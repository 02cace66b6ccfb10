// A request to watch a match as anyone on the domain may write it: unsigned, under any client id.
#pragma once

#include <cstdint>
#include <string>

#include "net/message_convert.h"
#include "net/sample.h"
#include "protocol/protocol_version.h"
#include "protocol/seat_request.h"

namespace pool::test {

/// The JoinRequest sample asking to watch `match` under `client`, numbered `request`, as the
/// protocol's conversion writes it (this build's protocol version, no key, no signature).
inline net::Sample<pool_JoinRequest> spectateRequest(const std::string& client,
                                                     const std::string& match,
                                                     std::uint32_t request) {
  protocol::SeatRequest r;
  r.client = client;
  r.request = request;
  r.protocol_version = protocol::kProtocolVersion;
  r.match = match;
  r.action = protocol::JoinAction::Spectate;
  r.seat = -1;
  return net::toWire(r);
}

}  // namespace pool::test
