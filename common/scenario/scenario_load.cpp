// Scenario files from disk: a path, or a bare scene name looked up in assets/scenes.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/input_file.h"
#include "scenario/scenario_sections.h"
#include "table/assets.h"

namespace pool::scenario {
namespace {

namespace fs = std::filesystem;

// "break" names a shared scene; anything with a folder or an extension is a path.
bool isBareName(const std::string& name) {
  return !name.empty() && name.find('/') == std::string::npos && !fs::path(name).has_extension();
}

Result<std::string> readText(const fs::path& path) {
  using R = Result<std::string>;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return R::fail("scenario: cannot read '" + path.string() + "': is a directory");
  auto text = readInputFile(path);
  if (!text) return R::fail("scenario: cannot read '" + path.string() + "': " + text.error());
  return text;
}

}  // namespace

Result<Scenario> loadScenario(const std::string& name_or_path) {
  fs::path path(name_or_path);
  std::error_code ec;
  if (isBareName(name_or_path) && !fs::exists(path, ec)) {
    const auto scene = table::findAsset("scenes/" + name_or_path + ".json");
    if (!scene)
      return Result<Scenario>::fail("scenario: no file '" + name_or_path +
                                    "' and no scene of that name in assets/scenes");
    path = *scene;
  }
  auto text = readText(path);
  if (!text) return Result<Scenario>::fail(text.error());
  return parseScenarioIn(*text, path.parent_path());
}

}  // namespace pool::scenario
