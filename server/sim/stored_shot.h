// A shot kept in a pool-server database as a physics-lab scenario, to run it again.
#pragma once

#include <cstdint>
#include <string>

#include "core/result.h"
#include "scenario/scenario.h"

namespace pool::sim {

/// The scenario of stored shot `shot` (its number, from 1) of match `match` in the database at
/// `db`: the match's table, the balls on the table at the strike, the command's cue. Fails with one
/// line when the file is missing or refused, or holds no such match or shot.
Result<scenario::Scenario> storedShotScenario(const std::string& db, const std::string& match,
                                              std::uint32_t shot);

}  // namespace pool::sim
