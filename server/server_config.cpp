// pool-server's settings in one table (flag, file key, field): flags over file over defaults.
#include "server/server_config.h"

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>
#include <vector>

namespace pool::server {

namespace {

using Json = nlohmann::json;

/// The value of `key` (or its underscore spelling) in `doc`, if present.
const Json* find(const Json& doc, const std::string& key) {
  std::string underscored = key;
  for (char& c : underscored) c = c == '-' ? '_' : c;
  for (const auto& k : {key, underscored}) {
    if (auto it = doc.find(k); it != doc.end()) return &*it;
  }
  return nullptr;
}

template <class T>
void take(const Json& doc, const std::string& key, T& into) {
  if (const Json* v = find(doc, key)) {
    try {
      if constexpr (std::is_same_v<T, std::string>) {
        // A name or a number ("game": 8 and "game": "three-cushion" both name a game).
        if (v->is_number_integer()) {
          into = std::to_string(v->get<long>());
          return;
        }
      }
      into = v->get<T>();
    } catch (const Json::exception&) {
      throw std::runtime_error(key + ": wrong type");
    }
  }
}

std::string readFile(const std::string& path, bool& ok) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  ok = static_cast<bool>(in);
  return text.str();
}

/// One thing pool-server can be told: its name ("--<key>" on the command line, "<key>" or its
/// underscore spelling in a --config file), its help line, and the config field it sets.
struct Setting {
  std::function<void(CLI::App&, ServerConfig&)> add_flag;        ///< the flag, into a config
  std::function<void(const Json&, ServerConfig&)> take;          ///< from a file; null: flag only
  std::function<void(const ServerConfig&, ServerConfig&)> copy;  ///< one config's value to another
  std::string key;
};

enum class Where : std::uint8_t { FlagAndFile, FlagOnly };

template <class T>
Setting setting(const char* key, T ServerConfig::*field, const char* help,
                Where where = Where::FlagAndFile) {
  Setting s;
  s.key = key;
  s.add_flag = [=](CLI::App& app, ServerConfig& c) {
    const std::string name = std::string("--") + key;
    if constexpr (std::is_same_v<T, bool>) {
      app.add_flag(name, c.*field, help);
    } else {
      app.add_option(name, c.*field, help);
    }
  };
  if (where == Where::FlagAndFile) {
    s.take = [=](const Json& doc, ServerConfig& c) { take(doc, key, c.*field); };
  }
  s.copy = [=](const ServerConfig& from, ServerConfig& to) { to.*field = from.*field; };
  return s;
}

/// Every setting, in the order of --help.
const std::vector<Setting>& settings() {
  using C = ServerConfig;
  static const std::vector<Setting> table = {
      setting("domain", &C::domain, "DDS domain id (0-232)"),
      setting("tables", &C::tables, "free tables kept open at all times"),
      setting("max-matches", &C::max_matches,
              "matches open at once, at most, free tables included (default 256)"),
      setting("snapshot-hz", &C::snapshot_hz, "frames per simulated second"),
      setting("fast", &C::fast, "publish frames unpaced (tests)"),
      setting("server-id", &C::server_id,
              "prefix of match ids, 1-24 of [A-Za-z0-9._-] (default: random hex)"),
      setting("grace", &C::grace, "seconds a vanished player's seat is kept"),
      setting("name", &C::name, "this server's name in logs"),
      setting("table", &C::table, "table spec name or path"),
      setting("log-level", &C::log_level, "trace, debug, info, warn, error, critical, off"),
      setting("db", &C::db,
              "SQLite file keeping every match (default $XDG_DATA_HOME/pool/pool.db)"),
      setting("game", &C::game,
              "game of the tables this server opens: 8, 9, 10, three-cushion or snooker (each of "
              "the last two on its own table, carom-match and snooker-12ft)"),
      setting("points", &C::points, "three-cushion: points that win a game (1-100, default 5)"),
      setting("race", &C::race, "racks (snooker: frames) to win a match (1-15)"),
      setting("rack-seed", &C::rack_seed,
              "non-zero: the racks of match n come from seed N + n, the same on every run (0: "
              "random)"),
      setting("breaks", &C::breaks, "who breaks the next rack: alternate or winner"),
      setting("shot-clock", &C::shot_clock, "off, or seconds per shot (5-600)"),
      setting("replay", &C::replay,
              "play stored match MATCH again as a new match for spectators (stores nothing)",
              Where::FlagOnly),
      setting("admin-socket", &C::admin_socket,
              "the operator's Unix socket, owner-only (default <db>.sock); see pool-server "
              "admin --help"),
  };
  return table;
}

Check<> refuse(const char* code, std::string sentence) {
  return Check<>::refuse(code, std::move(sentence));
}

}  // namespace

Check<> applyConfigJson(const std::string& text, ServerConfig& c) {
  const Json doc = Json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return refuse("not_an_object", "not a JSON object");
  try {
    for (const Setting& s : settings()) {
      if (s.take) s.take(doc, c);
    }
  } catch (const std::runtime_error& e) {
    return refuse("wrong_type", e.what());
  }
  return Check<>::pass();
}

Check<> checkConfig(const ServerConfig& c) {
  if (c.domain > 232) return refuse("bad_domain", "domain: must be 0-232");
  if (c.max_matches < 1 || c.max_matches > 10000)
    return refuse("bad_max_matches", "max-matches: must be 1-10000");
  if (c.tables < 0 || c.tables > c.max_matches) {
    return refuse("bad_tables",
                  "tables: must be 0-" + std::to_string(c.max_matches) + " (at most max-matches)");
  }
  if (!(c.snapshot_hz > 0.0 && c.snapshot_hz <= 1000.0))
    return refuse("bad_snapshot_hz", "snapshot-hz: must be in (0, 1000]");
  if (!(c.grace >= 0.0)) return refuse("bad_grace", "grace: must be >= 0");
  // Empty: drawn at random.
  if (!c.server_id.empty() && !protocol::validServerId(c.server_id)) {
    return refuse("bad_server_id",
                  "server-id: 1-" + std::to_string(kMaxServerIdLength) +
                      " letters, digits, '.', '_' or '-' (match ids are \"<server id>-<n>\" in "
                      "39 bytes)");
  }
  if (auto settings = matchSettingsOf(c); !settings)
    return refuse(settings.code().c_str(), settings.error());
  if (spdlog::level::from_str(c.log_level) == spdlog::level::off && c.log_level != "off") {
    return refuse("bad_log_level", "log-level: '" + c.log_level +
                                       "' is not one of trace, debug, info, warn, error, "
                                       "critical, off");
  }
  return Check<>::pass();
}

Result<protocol::MatchSettings> matchSettingsOf(const ServerConfig& c) {
  using R = Result<protocol::MatchSettings>;
  protocol::MatchSettings s;
  const auto game = rules::gameOfName(c.game);
  if (!game) return R::fail("bad_game", "game: must be 8, 9, 10, three-cushion or snooker");
  s.game = *game;
  s.race_to = c.race;
  if (s.game == rules::Game::ThreeCushion) s.points = c.points;
  const auto breaks = protocol::breakOrderOf(c.breaks);
  if (!breaks) return R::fail("bad_breaks", "breaks: must be alternate or winner");
  s.breaks = *breaks;
  const std::string clock_reason = "shot-clock: must be off or seconds per shot (5-600)";
  if (c.shot_clock != "off") {
    char* end = nullptr;
    s.shot_clock = std::strtod(c.shot_clock.c_str(), &end);
    if (c.shot_clock.empty() || end != c.shot_clock.c_str() + c.shot_clock.size() ||
        s.shot_clock == 0.0) {
      return R::fail("bad_shot_clock", clock_reason);
    }
  }
  if (auto ok = protocol::checkSettings(s); !ok) {
    if (ok.code() == "bad_race") {
      return R::fail("bad_race", "race: must be 1-" + std::to_string(protocol::kMaxRace));
    }
    if (ok.code() == "bad_points") {
      return R::fail("bad_points", "points: must be 1-" + std::to_string(protocol::kMaxPoints));
    }
    return R::fail("bad_shot_clock", clock_reason);
  }
  return R::ok(s);
}

ConfigOutcome parseConfig(int argc, const char* const* argv) {
  CLI::App app{
      "pool-server: the authoritative 8-, 9-, 10-ball and three-cushion match server over Cyclone "
      "DDS"};
  ServerConfig flags;
  std::string config_file;
  for (const Setting& s : settings()) {
    s.add_flag(app, flags);
    // --help lists the file right after the flags that shape the server's loop.
    if (s.key == "fast")
      app.add_option("--config", config_file, "JSON file with the same keys; flags win");
  }
  app.footer(
      "Operating a running server: pool-server status | pool-server admin VERB ... "
      "[--db PATH | --socket PATH] (pool-server admin --help)\n");
  ConfigOutcome out;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    out.exit_code = app.exit(e);
    return out;
  }
  if (!config_file.empty()) {
    bool ok = false;
    const std::string text = readFile(config_file, ok);
    auto applied = ok ? applyConfigJson(text, out.config)
                      : Check<>::refuse("unreadable", "cannot read the file");
    if (!applied) {
      std::cerr << "--config " << config_file << ": " << applied.error() << "\n";
      out.exit_code = 2;
      return out;
    }
  }
  // Flags given on the command line override the file.
  for (const Setting& s : settings()) {
    if (app.count("--" + s.key)) s.copy(flags, out.config);
  }
  if (auto ok = checkConfig(out.config); !ok) {
    std::cerr << ok.error() << "\n";
    out.exit_code = 2;
  }
  return out;
}

}  // namespace pool::server
