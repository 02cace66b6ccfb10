// pool-server's settings: command-line flags, an optional JSON file with the same keys, defaults.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "protocol/match_settings.h"
#include "protocol/server_signature.h"

namespace pool::server {

/// The longest --server-id (protocol/server_signature.h).
using protocol::kMaxServerIdLength;

/// Everything pool-server can be told.
struct ServerConfig {
  std::uint32_t domain = 0;          ///< DDS domain id, 0–232
  int tables = 0;                    ///< free tables kept open at all times
  int max_matches = 256;             ///< matches open at once, at most (free tables included)
  double snapshot_hz = 60.0;         ///< frames per simulated second, (0, 1000]
  bool fast = false;                 ///< publish frames unpaced
  std::string server_id;             ///< prefix of match ids; empty: random hex
  double grace = 30.0;               ///< s a vanished player's seat is kept
  std::string name = "pool-server";  ///< this server's name in logs
  std::string table = "wpa-9ft";     ///< table spec of every match
  std::string log_level = "info";    ///< spdlog level name
  std::string db;      ///< the SQLite file matches are kept in; empty: store::defaultDbPath()
  std::string replay;  ///< a stored match to play again for spectators (nothing is stored then)
  std::string admin_socket;  ///< the operator's Unix socket; empty: "<db>.sock"
  // Defaults of the tables this server opens (the first player at a table may choose others).
  std::string game = "8";  ///< 8, 9, 10, three-cushion or snooker (a game's name or number)
  int points = protocol::kDefaultPoints;  ///< three-cushion: points that win a game
  int race = 1;                           ///< racks to win a match
  std::uint64_t rack_seed = 0;            ///< non-zero: match n racks from seed rack_seed + n
  std::string breaks = "alternate";       ///< "alternate" or "winner"
  std::string shot_clock = "off";         ///< "off" or seconds per shot (5-600)
};

/// The table defaults of `config` (game, race, breaks, shot clock), or why they are not valid.
Result<protocol::MatchSettings> matchSettingsOf(const ServerConfig& config);

/// The outcome of reading the command line: run with `config`, or exit with `exit_code` (help,
/// or an error already printed).
struct ConfigOutcome {
  ServerConfig config;
  std::optional<int> exit_code;
};

/// Reads the flags of every setting (server_config.cpp's table: --domain, --tables, --max-matches,
/// --snapshot-hz, --fast, --server-id, --grace, --name, --table, --log-level, --db, --game,
/// --points, --race, --breaks, --shot-clock, --replay, --admin-socket) and --config FILE. The JSON
/// file gives values under the flags' names (without dashes; "snapshot-hz" or "snapshot_hz"; not
/// --replay); flags given on the command line win.
ConfigOutcome parseConfig(int argc, const char* const* argv);

/// Applies JSON `text` onto `config`, or refuses it naming the key ("not_an_object",
/// "wrong_type").
Check<> applyConfigJson(const std::string& text, ServerConfig& config);

/// Range checks: refuses with "<key>: <reason>".
Check<> checkConfig(const ServerConfig& config);

}  // namespace pool::server
