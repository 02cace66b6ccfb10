// A table and a shot written as a scenario file (SIM-CONTRACT.md), for a practice table's "save".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "physics/ball.h"
#include "physics/cue_strike.h"

namespace pool::scenario {

/// What a saved scenario holds: the table's name, coefficient overrides (scenario names), every
/// ball (those not on the table are left out of the file) and the shot (radians, as held).
struct ScenarioSource {
  std::string table = "wpa-9ft";
  std::vector<std::pair<std::string, double>> params;
  std::vector<physics::Ball> balls;
  physics::CueShot shot;
};

/// The scenario as JSON text that parseScenario and `pool-sim` accept: balls at their (x, y),
/// the shot's yaw and elevation in degrees; every number with the digits that read back to the
/// same double, and the degrees chosen (among the neighbours of the plain conversion) so that the
/// parser's conversion gives back the very radians when such degrees exist: the file then
/// replays the shot bit for bit.
std::string scenarioJson(const ScenarioSource& source);

}  // namespace pool::scenario
