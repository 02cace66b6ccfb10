// The parts of a scenario file, each read and checked on its own (table and params, balls, shot).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/check.h"
#include "scenario/scenario.h"

namespace pool::scenario {

/// Loads the spec named by `name_or_path` into s.spec. A relative path is tried against
/// `base_dir` first (the scenario file's folder), then as given. Refuses with "table: <reason>".
Check<> readTable(const std::string& name_or_path, const std::filesystem::path& base_dir,
                  Scenario& s);

/// Applies the `params` object (nullptr: none) through table::setParam, then table::validate.
/// Refuses with "params.<name>: <reason>".
Check<> readParams(const nlohmann::json* params, Scenario& s);

/// Applies the `models` object (nullptr: none) through table::setModel: the contact model of each
/// pair, over the spec's choice. Refuses with "models.<pair>: <reason>".
Check<> readModels(const nlohmann::json* models, Scenario& s);

/// Computes s.geometry from s.spec (after the params: the ball radius and nose height count).
Check<> buildGeometry(Scenario& s);

/// Fills s.balls from `rack` and `balls` (either may be nullptr), the cue ball on the head spot
/// unless placed, then checks the placement. Refuses with "balls...: <reason>" / "rack: <reason>".
Check<> readBalls(const nlohmann::json* balls, const nlohmann::json* rack, Scenario& s);

/// Reads the `shot` object into s.shot (radians inside) and validates it against the params.
/// Refuses with "shot.<field>: <reason>".
Check<> readShot(const nlohmann::json& shot, Scenario& s);

/// parseScenario with relative table paths resolved against `base_dir` first.
Result<Scenario> parseScenarioIn(const std::string& json_text,
                                 const std::filesystem::path& base_dir);

}  // namespace pool::scenario
