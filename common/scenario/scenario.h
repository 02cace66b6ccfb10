// Scenario files of the physics lab (SIM-CONTRACT.md): parsing with one-line errors, and the shot's
// result as JSON.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"
#include "physics/ball.h"
#include "physics/cue_strike.h"
#include "physics/simulation.h"
#include "table/rack.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::scenario {

/// A parsed, validated scenario: the table (with params applied), its balls at rest, the shot.
struct Scenario {
  table::TableSpec spec;
  table::TableGeometry geometry;
  std::vector<physics::Ball> balls;  ///< sorted by id
  physics::CueShot shot;
  physics::SimOptions options;
  std::uint64_t seed = 0;
  /// How `rack` lays out its balls: frozen (default) or with a hand rack's gaps, from `seed`.
  table::RackGenerator rack_generator = table::RackGenerator::Frozen;
};

/// Parses and validates scenario JSON text. A failure's reason is one line naming the field,
/// e.g. "shot.speed: must be in (0, 12] m/s".
Result<Scenario> parseScenario(const std::string& json_text);

/// Loads a scenario file (assets/scenes/<name>.json when given a bare scene name such as "break").
Result<Scenario> loadScenario(const std::string& name_or_path);

/// Runs the scenario's shot on a fresh simulation.
Result<physics::ShotOutcome> runScenario(const Scenario& scenario);

/// The result JSON of SIM-CONTRACT.md (version 1), byte-identical for the same outcome.
std::string resultJson(const Scenario& scenario, const physics::ShotOutcome& outcome);

/// A top-down SVG: table, cushions, pockets to scale, every ball's path, events marked.
std::string plotSvg(const Scenario& scenario, const physics::ShotOutcome& outcome);

/// Samples per second of the paths in a plot, when the scenario asks for fewer.
constexpr double kPlotSampleHz = 200.0;

/// The outcome to plot: `outcome` itself when it has a trajectory of at least kPlotSampleHz,
/// otherwise the same shot run again with that sampling (sampling changes no event or result).
Result<physics::ShotOutcome> runForPlot(const Scenario& scenario,
                                        const physics::ShotOutcome& outcome);

}  // namespace pool::scenario
