// A fresh rack at rest on a loaded table: the object balls from the foot spot, the cue ball behind
// the head string.
#pragma once

#include <cstdint>
#include <vector>

#include "game/loaded_table.h"
#include "physics/ball.h"
#include "table/rack.h"

namespace pool::game {

/// How far behind the head spot (toward the head cushion) a breaking cue ball is put, m. The
/// rules want a cue ball in hand strictly behind the head string, which runs through the head
/// spot.
inline constexpr double kBreakCueSetback = 0.01;

/// A fresh rack of `type` at rest: the object balls from the foot spot, laid out by `generator`
/// from `seed` (table::rackFor), and the cue ball kBreakCueSetback behind the head spot (a carom
/// opening's cue balls where the opening puts them). In id order.
std::vector<physics::Ball> rackLayout(
    const LoadedTable& table, std::uint64_t seed, table::RackType type = table::RackType::EightBall,
    table::RackGenerator generator = table::RackGenerator::Frozen);

}  // namespace pool::game
