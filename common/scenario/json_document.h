// Strict JSON reading for scenario files: one-line errors naming the field, no duplicated keys.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/result.h"

namespace pool::scenario {

/// Parses `text` as one JSON document. Fails with one line: "scenario: empty input",
/// "scenario: invalid JSON at line L, column C: ...", "<field>: duplicated key" or
/// "<field>: must be a finite number, got 1e999" (a number too large for a double).
Result<nlohmann::json> parseJsonDocument(const std::string& text);

/// Replaces line breaks and other control characters so that `text` prints as one line.
std::string oneLine(std::string text);

}  // namespace pool::scenario
