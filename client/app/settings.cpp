// Settings file reading and writing.
#include "client/app/settings.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include "client/net/player_identity.h"

namespace pool::app {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

/// One number, nothing after it, finite and in [lo, hi].
bool readNumber(const std::string& value, double lo, double hi, double& out) {
  std::istringstream v(value);
  std::string rest;
  double read = 0.0;
  if (!(v >> read) || (v >> rest) || !std::isfinite(read) || read < lo || read > hi) return false;
  out = read;
  return true;
}

bool readBool(const std::string& value, bool& out) {
  if (value == "true" || value == "on" || value == "1") {
    out = true;
    return true;
  }
  if (value == "false" || value == "off" || value == "0") {
    out = false;
    return true;
  }
  return false;
}

}  // namespace

std::filesystem::path defaultSettingsPath() {
  const auto players = client::defaultIdentityDir();
  if (players.empty()) return {};
  return players.parent_path() / "settings.conf";
}

bool knownPane(const std::string& name) {
  return name == "match" || name == "shot" || name == "log";
}

bool knownQuality(const std::string& name) {
  return name == "auto" || name == "high" || name == "full" || name == "light";
}

Result<Settings> loadSettings(const std::filesystem::path& path) {
  using R = Result<Settings>;
  Settings s;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return R::ok(s);
  std::ifstream in(path);
  if (!in) return R::fail("cannot read " + path.string());
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    line = trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    const auto eq = line.find('=');
    const std::string where = path.string() + " line " + std::to_string(number) + ": ";
    if (eq == std::string::npos) return R::fail(where + "expected key = value");
    const std::string key = trim(line.substr(0, eq));
    const std::string value = trim(line.substr(eq + 1));
    bool ok = true;
    if (key == "full_screen") {
      ok = readBool(value, s.full_screen);
    } else if (key == "aim_line") {
      ok = readBool(value, s.aim_line);
    } else if (key == "follow_cue") {
      ok = readBool(value, s.follow_cue);
    } else if (key == "vectors") {
      ok = readBool(value, s.vectors);
    } else if (key == "quality") {
      ok = knownQuality(value);
      if (ok) s.quality = value;
    } else if (key == "volume") {
      ok = readNumber(value, 0.0, 1.0, s.volume);
    } else if (key == "stroke_mm") {
      ok = readNumber(value, 0.2, 5.0, s.stroke_mm);
    } else if (key.rfind("pane_", 0) == 0 && knownPane(key.substr(5))) {
      // "x, y": two fractions of the window.
      const auto comma = value.find(',');
      std::array<double, 2> at{};
      ok = comma != std::string::npos &&
           readNumber(trim(value.substr(0, comma)), 0.0, 1.0, at[0]) &&
           readNumber(trim(value.substr(comma + 1)), 0.0, 1.0, at[1]);
      if (ok) s.pane_places[key.substr(5)] = at;
    } else {
      return R::fail(where + "unknown setting '" + key + "'");
    }
    if (!ok) return R::fail(where + "bad value '" + value + "' for " + key);
  }
  return R::ok(s);
}

Result<bool> saveSettings(const std::filesystem::path& path, const Settings& s) {
  using R = Result<bool>;
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return R::fail("cannot make " + path.parent_path().string() + ": " + ec.message());
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << "# pool-client settings\n"
        << "full_screen = " << (s.full_screen ? "true" : "false") << '\n'
        << "volume = " << s.volume << '\n'
        << "aim_line = " << (s.aim_line ? "true" : "false") << '\n'
        << "vectors = " << (s.vectors ? "true" : "false") << '\n'
        << "quality = " << s.quality << '\n'
        << "stroke_mm = " << s.stroke_mm << '\n'
        << "follow_cue = " << (s.follow_cue ? "true" : "false") << '\n';
    for (const auto& [pane, at] : s.pane_places) {
      out << "pane_" << pane << " = " << at[0] << ", " << at[1] << '\n';
    }
    if (!out.flush()) return R::fail("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) return R::fail("cannot replace " + path.string() + ": " + ec.message());
  return R::ok(true);
}

}  // namespace pool::app
