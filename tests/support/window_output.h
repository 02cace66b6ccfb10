// The windowed client's output as tests read it: its JSON lines of one event (--json), and the
// whole text of a file (its standard error).
#pragma once

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace pool::test {

/// Every line of `path` that parses as JSON with "event" equal to `event`, in order.
inline std::vector<nlohmann::json> jsonLines(const std::string& path, const std::string& event) {
  std::vector<nlohmann::json> out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    auto json = nlohmann::json::parse(line, nullptr, false);
    if (!json.is_discarded() && json.value("event", "") == event) out.push_back(json);
  }
  return out;
}

/// The whole text of `path` (empty when it cannot be read).
inline std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace pool::test
