// Schema version 1 (matches, seats, shots), 2 (seats' public keys), 3 (banned keys), 4 (the
// server's own key), 5 (match settings), 6 (rack generators), 7 (ratings), 8 (statistics) and 9
// (tournaments), and the refusals.
#include "server/store/schema.h"

#include <array>
#include <filesystem>
#include <fstream>

namespace pool::store {

namespace {

constexpr const char* kVersion1 = R"sql(
CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE matches(
  id TEXT PRIMARY KEY, number INTEGER NOT NULL, name TEXT NOT NULL, table_name TEXT NOT NULL,
  rack_seed INTEGER NOT NULL, layouts INTEGER NOT NULL, started INTEGER NOT NULL,
  closed INTEGER NOT NULL, client_made INTEGER NOT NULL, shot_number INTEGER NOT NULL,
  rack INTEGER NOT NULL, revision INTEGER NOT NULL, last_verdict TEXT NOT NULL,
  game TEXT NOT NULL, balls TEXT NOT NULL);
CREATE TABLE seats(
  match TEXT NOT NULL REFERENCES matches(id), seat INTEGER NOT NULL, player TEXT NOT NULL,
  token INTEGER NOT NULL, client TEXT NOT NULL, last_seq INTEGER NOT NULL,
  fouls INTEGER NOT NULL, racks_won INTEGER NOT NULL, wants_rematch INTEGER NOT NULL,
  PRIMARY KEY(match, seat));
CREATE TABLE shots(
  id INTEGER PRIMARY KEY, match TEXT NOT NULL REFERENCES matches(id),
  shot_number INTEGER NOT NULL, shoots INTEGER NOT NULL, seat INTEGER NOT NULL,
  seq INTEGER NOT NULL, command TEXT NOT NULL, state TEXT NOT NULL, before TEXT NOT NULL,
  intent TEXT NOT NULL, events TEXT NOT NULL, after TEXT NOT NULL, verdict TEXT NOT NULL,
  verdict_text TEXT NOT NULL);
CREATE INDEX shots_of_match ON shots(match, shot_number);
)sql";

// Signed commands: the key each seat's commands are signed with (empty: unsigned).
constexpr const char* kVersion2 = R"sql(
ALTER TABLE seats ADD COLUMN public_key BLOB NOT NULL DEFAULT x'';
)sql";

// Operating a server: the public keys the operator banned, with the reason and when.
constexpr const char* kVersion3 = R"sql(
CREATE TABLE bans(public_key BLOB PRIMARY KEY, reason TEXT NOT NULL, banned_at TEXT NOT NULL);
)sql";

// Server-signed samples: the server's Ed25519 key pair, made once (at most one row).
constexpr const char* kVersion4 = R"sql(
CREATE TABLE server_key(
  id INTEGER PRIMARY KEY CHECK (id = 1), secret_key BLOB NOT NULL, created INTEGER NOT NULL);
)sql";

// Match settings (game, race, breaks, shot clock) as JSON; '{}': an 8-ball match of one rack.
constexpr const char* kVersion5 = R"sql(
ALTER TABLE matches ADD COLUMN settings TEXT NOT NULL DEFAULT '{}';
)sql";

// The rack generator of each match (table::RackGenerator); 0, frozen: matches stored before.
constexpr const char* kVersion6 = R"sql(
ALTER TABLE matches ADD COLUMN rack_generator INTEGER NOT NULL DEFAULT 0;
)sql";

// Ratings: each player's Glicko-2 rating per game (the key it signs with), and every rated
// result with the ratings before and after it (one row per decided match: its id, and the rack
// and shot it was decided at, which a rematch moves on).
constexpr const char* kVersion7 = R"sql(
CREATE TABLE ratings(
  public_key BLOB NOT NULL, game INTEGER NOT NULL, rating REAL NOT NULL, deviation REAL NOT NULL,
  volatility REAL NOT NULL, matches INTEGER NOT NULL, PRIMARY KEY(public_key, game));
CREATE TABLE rated_results(
  match TEXT NOT NULL, rack INTEGER NOT NULL, shot_number INTEGER NOT NULL, game INTEGER NOT NULL,
  winner_key BLOB NOT NULL, loser_key BLOB NOT NULL,
  winner_before REAL NOT NULL, winner_after REAL NOT NULL,
  loser_before REAL NOT NULL, loser_after REAL NOT NULL,
  PRIMARY KEY(match, rack, shot_number));
)sql";

// Statistics: each player's counts per game (the key it signs with), added to with every stored
// stroke, the most recently added to found by `updated`; and each match seat's inning in play
// (its run; whether it began with the seat's own break), which a player's other matches leave
// alone (stat_book.h).
constexpr const char* kVersion8 = R"sql(
CREATE TABLE player_stats(
  public_key BLOB NOT NULL, game INTEGER NOT NULL, name TEXT NOT NULL,
  matches INTEGER NOT NULL DEFAULT 0, matches_won INTEGER NOT NULL DEFAULT 0,
  racks INTEGER NOT NULL DEFAULT 0, racks_won INTEGER NOT NULL DEFAULT 0,
  strokes INTEGER NOT NULL DEFAULT 0, attempts INTEGER NOT NULL DEFAULT 0,
  pots INTEGER NOT NULL DEFAULT 0, breaks INTEGER NOT NULL DEFAULT 0,
  break_pots INTEGER NOT NULL DEFAULT 0, break_and_runs INTEGER NOT NULL DEFAULT 0,
  fouls INTEGER NOT NULL DEFAULT 0, safeties INTEGER NOT NULL DEFAULT 0,
  high_run INTEGER NOT NULL DEFAULT 0, updated INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY(public_key, game));
CREATE INDEX player_stats_by_update ON player_stats(updated);
CREATE TABLE stat_innings(
  match TEXT NOT NULL, seat INTEGER NOT NULL, run INTEGER NOT NULL, from_break INTEGER NOT NULL,
  PRIMARY KEY(match, seat));
)sql";

// Tournaments: each one the server runs, by its id and number (the counter of tournaments
// opened), its settings (format, game, race, capacity), its phase, the entries taken before it
// starts (JSON), the tournament itself once started (pool_tournament's JSON; empty before) and
// the server match id of each tournament match index (a JSON array of strings, "" for none).
// The texts are opaque to the store (tournament_book.h).
constexpr const char* kVersion9 = R"sql(
CREATE TABLE tournaments(
  id TEXT PRIMARY KEY, number INTEGER NOT NULL, name TEXT NOT NULL, format INTEGER NOT NULL,
  game INTEGER NOT NULL, race_to INTEGER NOT NULL, capacity INTEGER NOT NULL,
  phase INTEGER NOT NULL, entries TEXT NOT NULL, state TEXT NOT NULL, match_ids TEXT NOT NULL,
  created INTEGER NOT NULL);
)sql";

// A tournament's options beyond its settings (JSON, opaque to the store): its handicap, and who
// opened it (a player's name and key; none: the operator).
constexpr const char* kVersion10 = R"sql(
ALTER TABLE tournaments ADD COLUMN options TEXT NOT NULL DEFAULT '{}';
)sql";

constexpr std::array<const char*, kSchemaVersion> kSteps{kVersion1, kVersion2, kVersion3, kVersion4,
                                                         kVersion5, kVersion6, kVersion7, kVersion8,
                                                         kVersion9, kVersion10};

std::uint64_t bigEndian(const unsigned char* p, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | p[i];
  return v;
}

/// The header's promise: the file holds page_count pages of page_size bytes.
Check<> checkHeader(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return Check<>::refuse("unreadable", "cannot read it: " + ec.message());
  if (size == 0) return Check<>::pass();
  std::array<unsigned char, 100> header{};
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(header.data()), header.size());
  static const char kMagic[] = "SQLite format 3";
  if (in.gcount() < 100 || std::equal(kMagic, kMagic + 16, header.begin()) == false) {
    return Check<>::refuse("not_sqlite", "not an SQLite database");
  }
  const std::uint64_t raw_page = bigEndian(&header[16], 2);
  const std::uint64_t page_size = raw_page == 1 ? 65536 : raw_page;
  const std::uint64_t pages = bigEndian(&header[28], 4);
  const std::string wal = path + "-wal";
  // With a write-ahead log beside it the main file may lag its header until a checkpoint.
  const bool has_wal = std::filesystem::exists(wal, ec) && std::filesystem::file_size(wal, ec) > 0;
  if (!has_wal && pages * page_size > size) {
    return Check<>::refuse("truncated", "truncated (" + std::to_string(size) + " of " +
                                            std::to_string(pages * page_size) + " bytes)");
  }
  return Check<>::pass();
}

/// SQLite's multi-line report as one line.
std::string oneLine(std::string text) {
  const std::string banner = "*** in database main ***\n";
  if (text.rfind(banner, 0) == 0) text.erase(0, banner.size());
  for (char& c : text) c = c == '\n' ? ' ' : c;
  return text;
}

}  // namespace

std::span<const char* const> migrationSteps() {
  return kSteps;
}

Check<> checkFile(const std::string& path) {
  if (auto ok = checkHeader(path); !ok) return ok;
  auto db = Database::open(path, /*read_only=*/true, /*create=*/false);
  if (!db) return Check<>::refuse("unreadable", db.error());
  try {
    auto check = db->prepare("PRAGMA quick_check");
    if (check.step() && check.text(0) != "ok") {
      return Check<>::refuse("failed_integrity_check",
                             "fails its integrity check: " + oneLine(check.text(0)));
    }
    const std::int64_t app = db->integer("PRAGMA application_id");
    const std::int64_t version = db->integer("PRAGMA user_version");
    const std::int64_t tables = db->integer("SELECT count(*) FROM sqlite_master");
    if (app != kApplicationId && (app != 0 || tables > 0))
      return Check<>::refuse("not_pool_database", "not a pool database");
    if (version > kSchemaVersion) {
      return Check<>::refuse("newer_schema", "schema version " + std::to_string(version) +
                                                 " is newer than this program's " +
                                                 std::to_string(kSchemaVersion));
    }
  } catch (const StoreError& e) {
    return Check<>::refuse("store_error", e.what());
  }
  return Check<>::pass();
}

void migrate(Database& db) {
  for (auto version = db.integer("PRAGMA user_version"); version < kSchemaVersion; ++version) {
    Transaction step(db);
    db.exec(kSteps[static_cast<std::size_t>(version)]);
    db.exec("PRAGMA user_version = " + std::to_string(version + 1));
    db.exec("PRAGMA application_id = " + std::to_string(kApplicationId));
    step.commit();
  }
}

}  // namespace pool::store
