// Flags over file over defaults, with CLI11 and nlohmann-json.
#include "server/server_config.h"

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

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

}  // namespace

std::string applyConfigJson(const std::string& text, ServerConfig& c) {
  const Json doc = Json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return "not a JSON object";
  try {
    take(doc, "domain", c.domain);
    take(doc, "tables", c.tables);
    take(doc, "max-matches", c.max_matches);
    take(doc, "snapshot-hz", c.snapshot_hz);
    take(doc, "fast", c.fast);
    take(doc, "server-id", c.server_id);
    take(doc, "grace", c.grace);
    take(doc, "name", c.name);
    take(doc, "table", c.table);
    take(doc, "log-level", c.log_level);
    take(doc, "db", c.db);
    take(doc, "admin-socket", c.admin_socket);
    take(doc, "game", c.game);
    take(doc, "race", c.race);
    take(doc, "breaks", c.breaks);
    take(doc, "shot-clock", c.shot_clock);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return {};
}

std::string checkConfig(const ServerConfig& c) {
  if (c.domain > 232) return "domain: must be 0-232";
  if (c.max_matches < 1 || c.max_matches > 10000) return "max-matches: must be 1-10000";
  if (c.tables < 0 || c.tables > c.max_matches) {
    return "tables: must be 0-" + std::to_string(c.max_matches) + " (at most max-matches)";
  }
  if (!(c.snapshot_hz > 0.0 && c.snapshot_hz <= 1000.0)) return "snapshot-hz: must be in (0, 1000]";
  if (!(c.grace >= 0.0)) return "grace: must be >= 0";
  // Empty: drawn at random.
  if (!c.server_id.empty() && !protocol::validServerId(c.server_id)) {
    return "server-id: 1-" + std::to_string(kMaxServerIdLength) +
           " letters, digits, '.', '_' or '-' (match ids are \"<server id>-<n>\" in 39 bytes)";
  }
  if (std::string why; !matchSettingsOf(c, &why)) return why;
  if (spdlog::level::from_str(c.log_level) == spdlog::level::off && c.log_level != "off") {
    return "log-level: '" + c.log_level +
           "' is not one of trace, debug, info, warn, error, "
           "critical, off";
  }
  return {};
}

std::optional<protocol::MatchSettings> matchSettingsOf(const ServerConfig& c, std::string* why) {
  auto refuse = [why](std::string reason) {
    if (why) *why = std::move(reason);
    return std::optional<protocol::MatchSettings>{};
  };
  protocol::MatchSettings s;
  const auto game = rules::gameOfNumber(c.game);
  if (!game) return refuse("game: must be 8, 9 or 10");
  s.game = *game;
  s.race_to = c.race;
  const auto breaks = protocol::breakOrderOf(c.breaks);
  if (!breaks) return refuse("breaks: must be alternate or winner");
  s.breaks = *breaks;
  if (c.shot_clock != "off") {
    char* end = nullptr;
    s.shot_clock = std::strtod(c.shot_clock.c_str(), &end);
    if (c.shot_clock.empty() || end != c.shot_clock.c_str() + c.shot_clock.size() ||
        s.shot_clock == 0.0) {
      return refuse("shot-clock: must be off or seconds per shot (5-600)");
    }
  }
  if (std::string reason = protocol::checkSettings(s); !reason.empty()) {
    return refuse(reason.rfind("race", 0) == 0
                      ? "race: must be 1-" + std::to_string(protocol::kMaxRace)
                      : "shot-clock: must be off or seconds per shot "
                        "(5-600)");
  }
  return s;
}

ConfigOutcome parseConfig(int argc, const char* const* argv) {
  CLI::App app{"pool-server: the authoritative 8-, 9- and 10-ball match server over Cyclone DDS"};
  ServerConfig flags;
  std::string config_file;
  app.add_option("--domain", flags.domain, "DDS domain id (0-232)");
  app.add_option("--tables", flags.tables, "free tables kept open at all times");
  app.add_option("--max-matches", flags.max_matches,
                 "matches open at once, at most, free tables included (default 256)");
  app.add_option("--snapshot-hz", flags.snapshot_hz, "frames per simulated second");
  app.add_flag("--fast", flags.fast, "publish frames unpaced (tests)");
  app.add_option("--config", config_file, "JSON file with the same keys; flags win");
  app.add_option("--server-id", flags.server_id,
                 "prefix of match ids, 1-24 of [A-Za-z0-9._-] (default: random hex)");
  app.add_option("--grace", flags.grace, "seconds a vanished player's seat is kept");
  app.add_option("--name", flags.name, "this server's name in logs");
  app.add_option("--table", flags.table, "table spec name or path");
  app.add_option("--log-level", flags.log_level, "trace, debug, info, warn, error, critical, off");
  app.add_option("--db", flags.db,
                 "SQLite file keeping every match (default $XDG_DATA_HOME/pool/pool.db)");
  app.add_option("--game", flags.game, "game of the tables this server opens: 8, 9 or 10");
  app.add_option("--race", flags.race, "racks to win a match (1-15)");
  app.add_option("--breaks", flags.breaks, "who breaks the next rack: alternate or winner");
  app.add_option("--shot-clock", flags.shot_clock, "off, or seconds per shot (5-600)");
  app.add_option("--replay", flags.replay,
                 "play stored match MATCH again as a new match for spectators (stores nothing)");
  app.add_option("--admin-socket", flags.admin_socket,
                 "the operator's Unix socket, owner-only (default <db>.sock); see pool-server "
                 "admin --help");
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
    std::string error = ok ? applyConfigJson(text, out.config) : "cannot read the file";
    if (!error.empty()) {
      std::cerr << "--config " << config_file << ": " << error << "\n";
      out.exit_code = 2;
      return out;
    }
  }
  // Flags given on the command line override the file.
  ServerConfig& c = out.config;
  if (app.count("--domain")) c.domain = flags.domain;
  if (app.count("--tables")) c.tables = flags.tables;
  if (app.count("--max-matches")) c.max_matches = flags.max_matches;
  if (app.count("--snapshot-hz")) c.snapshot_hz = flags.snapshot_hz;
  if (app.count("--fast")) c.fast = flags.fast;
  if (app.count("--server-id")) c.server_id = flags.server_id;
  if (app.count("--grace")) c.grace = flags.grace;
  if (app.count("--name")) c.name = flags.name;
  if (app.count("--table")) c.table = flags.table;
  if (app.count("--log-level")) c.log_level = flags.log_level;
  if (app.count("--db")) c.db = flags.db;
  if (app.count("--replay")) c.replay = flags.replay;
  if (app.count("--admin-socket")) c.admin_socket = flags.admin_socket;
  if (app.count("--game")) c.game = flags.game;
  if (app.count("--race")) c.race = flags.race;
  if (app.count("--breaks")) c.breaks = flags.breaks;
  if (app.count("--shot-clock")) c.shot_clock = flags.shot_clock;
  if (auto error = checkConfig(c); !error.empty()) {
    std::cerr << error << "\n";
    out.exit_code = 2;
  }
  return out;
}

}  // namespace pool::server
