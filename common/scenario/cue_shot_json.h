// A cue shot as a JSON object, the way the server's store and the client's JSON lines write it.
#pragma once

#include <nlohmann/json.hpp>

#include "physics/cue_strike.h"

namespace pool::scenario {

/// `shot` as {"yaw", "tip_side", "tip_height", "elevation", "speed", "speed_is_ball"}, each value
/// as it is held (radians, fractions of R, m/s; not the degrees of a scenario file). Callers add
/// their own keys with `update`.
nlohmann::json cueShotJson(const physics::CueShot& shot);

}  // namespace pool::scenario
