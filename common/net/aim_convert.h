// The shooter's aim to and from its two wire samples: the player's signed AimCommand and the
// server's relayed CueAim.
#pragma once

#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"
#include "protocol/aim_sample.h"

namespace pool::net {

/// The player's sample: every field of `aim`, its signature included.
Sample<pool_AimCommand> toAimCommand(const protocol::AimSample& aim);
/// The relayed sample: `aim` without token or player signature (the server seals it).
Sample<pool_CueAim> toCueAim(const protocol::AimSample& aim);

/// An AimCommand read back; fails on an unterminated match id or a signature longer than 64
/// bytes. The values are not range-checked here (protocol::checkAim does).
Result<protocol::AimSample> fromWire(const pool_AimCommand& command);
/// A CueAim read back; fails on an unterminated match id or values checkAim refuses.
Result<protocol::AimSample> fromWire(const pool_CueAim& aim);

}  // namespace pool::net
