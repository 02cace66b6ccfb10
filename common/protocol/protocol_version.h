// The protocol version of this build, readable without the generated wire types.
#pragma once

namespace pool::protocol {

/// pool.idl's PROTOCOL_VERSION (net/messages.h checks that the two agree). 3: one signed envelope
/// for every player message, signed seat requests.
inline constexpr unsigned kProtocolVersion = 3;

}  // namespace pool::protocol
