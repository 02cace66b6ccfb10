// Tournaments on the wire: a TournamentView as a TournamentInfo sample and back, bounds checked.
#pragma once

#include "core/result.h"
#include "net/messages.h"
#include "net/sample.h"
#include "protocol/tournament_view.h"

namespace pool::net {

/// `view` as a sample (entrants past 32 and matches past 64 are cut; counts clamped to a byte).
Sample<pool_TournamentInfo> toWire(const protocol::TournamentView& view);
/// Reads a sample: texts within their bounds, a known format, phase and game, entrant indices in
/// range.
Result<protocol::TournamentView> fromWire(const pool_TournamentInfo& info);

}  // namespace pool::net
