// A stored shot written as a pool-sim scenario file: the table, the layout at the strike and the
// cue as played, under a name that says which match and shot it was.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/result.h"
#include "protocol/history.h"
#include "scenario/scenario_write.h"

namespace pool::ui {

/// What the scenario of a stored shot holds: its table, its layout at the strike and its cue.
scenario::ScenarioSource shotScenario(const protocol::HistoryShot& shot);

/// "<match>-shot-<n>.json", with every character of the match id but letters, digits, '-' and '_'
/// written as '_' (the id is the server's: it never names another folder).
std::string scenarioFileName(const std::string& match, std::uint32_t shot);

/// Writes the scenario of `shot` (scenario::scenarioJson) as scenarioFileName in `dir`; returns
/// the absolute path written, or why nothing was (one line): a choice that re-racked has no
/// stroke to export, and a scenario file cannot say that another ball than the cue ball was
/// struck (three-cushion's second player's).
Result<std::filesystem::path> exportShot(const protocol::HistoryShot& shot,
                                         const std::filesystem::path& dir);

}  // namespace pool::ui
