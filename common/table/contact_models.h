// Which contact model the physics uses for each pair of bodies, by name, as a table spec sets it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/check.h"

namespace pool::table {

/// The model chosen for each contact pair (names as in SIM-CONTRACT.md's `models`).
struct ContactModels {
  std::string ball_cloth = "leckie_greenspan2005";  ///< sliding, rolling, spin decay on the cloth
  std::string ball_ball = "alciatore";              ///< ball–ball impulse with throw
  std::string ball_cushion = "mathavan2010";        ///< ball against a cushion nose or jaw point
  std::string ball_slate = "rigid_coulomb";  ///< a ball landing on (or driven into) the slate
  std::string cue_ball = "alciatore";        ///< the cue tip's strike
};

/// The contact pairs, in SIM-CONTRACT.md's order: ball_cloth, ball_ball, ball_cushion, ...
const std::vector<std::string_view>& contactPairs();

/// The model names known for `pair` (empty for an unknown pair).
const std::vector<std::string_view>& knownModels(std::string_view pair);

/// Sets the model of `pair` to `name`, or refuses with a one-line reason without the field name
/// ("unknown contact pair", "unknown model 'x' (known: a, b)"); nothing changes on a refusal.
Check<> setModel(ContactModels& models, std::string_view pair, std::string_view name);

}  // namespace pool::table
