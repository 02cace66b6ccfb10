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
/// same double (the degrees are the one conversion that may move a last bit).
std::string scenarioJson(const ScenarioSource& source);

}  // namespace pool::scenario
