// Reading and writing matches, seats and commands; one transaction per change.
#include "server/store/match_store.h"

#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "rules/game_rules.h"
#include "server/store/online_backup.h"
#include "server/store/rating_book.h"
#include "server/store/record_json.h"
#include "server/store/schema.h"
#include "server/store/stat_book.h"

namespace pool::store {

namespace {

constexpr const char* kMatchColumns =
    "id, number, name, table_name, rack_seed, layouts, started, closed, client_made, shot_number, "
    "rack, revision, last_verdict, game, balls, settings, rack_generator";

std::int64_t i64(std::uint64_t v) {
  return static_cast<std::int64_t>(v);
}

std::uint64_t u64(std::int64_t v) {
  return static_cast<std::uint64_t>(v);
}

server::MatchSnapshot matchAt(const Statement& row) {
  server::MatchSnapshot m;
  m.id = row.text(0);
  m.number = u64(row.integer(1));
  m.name = row.text(2);
  m.rack_seed = u64(row.integer(4));
  m.layouts = u64(row.integer(5));
  m.started = row.integer(6) != 0;
  m.closed = row.integer(7) != 0;
  m.client_made = row.integer(8) != 0;
  m.shot_number = static_cast<std::uint32_t>(row.integer(9));
  m.rack = static_cast<std::uint32_t>(row.integer(10));
  m.revision = u64(row.integer(11));
  m.last_verdict = row.text(12);
  m.game = gameFrom(row.text(13));
  m.balls = ballsFrom(row.text(14));
  m.settings = settingsFrom(row.text(15));
  const auto generator = table::rackGeneratorOf(row.integer(16));
  if (!generator) {
    throw StoreError("stored match " + m.id + " unreadable: rack generator " +
                     std::to_string(row.integer(16)) + " is not one this program knows");
  }
  m.rack_generator = *generator;
  return m;
}

}  // namespace

bool resumable(const server::MatchSnapshot& m) {
  return !m.closed && (m.seats[0].taken() || m.seats[1].taken());
}

std::string defaultDbPath() {
  const char* xdg = std::getenv("XDG_DATA_HOME");
  if (xdg && *xdg) return std::string(xdg) + "/pool/pool.db";
  const char* home = std::getenv("HOME");
  return std::string(home && *home ? home : ".") + "/.local/share/pool/pool.db";
}

Result<std::unique_ptr<MatchStore>> MatchStore::open(const std::string& path) {
  using Out = Result<std::unique_ptr<MatchStore>>;
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    if (auto ok = checkFile(path); !ok) return Out::fail(ok.code(), path + ": " + ok.error());
  } else {
    const auto folder = std::filesystem::path(path).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder, ec);
    if (ec) return Out::fail(path + ": cannot create its folder: " + ec.message());
  }
  auto db = Database::open(path, /*read_only=*/false, /*create=*/true);
  if (!db) return Out::fail(path + ": " + db.error());
  try {
    // Every commit is on disk before the server publishes what it stored. One server per file:
    // the lock taken by the first write is held until the process ends (a crash frees it).
    db->exec(
        "PRAGMA busy_timeout = 2000; PRAGMA locking_mode = EXCLUSIVE; "
        "PRAGMA journal_mode = WAL; PRAGMA synchronous = FULL");
    migrate(*db);
    db->exec("BEGIN IMMEDIATE; COMMIT");
  } catch (const StoreError& e) {
    return Out::fail(path + ": " + e.what());
  }
  std::error_code absolute_ec;
  const auto where = std::filesystem::absolute(path, absolute_ec);
  return Out::ok(std::unique_ptr<MatchStore>(
      new MatchStore(std::move(*db), absolute_ec ? path : where.string())));
}

// ---- Meta ---------------------------------------------------------------------------------------

std::string MatchStore::readMeta(const std::string& key) {
  auto q = db_.prepare("SELECT value FROM meta WHERE key = ?");
  q.bind(1, key);
  return q.step() ? q.text(0) : std::string();
}

void MatchStore::writeMeta(const std::string& key, const std::string& value) {
  db_.prepare(
         "INSERT INTO meta(key, value) VALUES(?, ?) ON CONFLICT(key) DO UPDATE SET value = "
         "excluded.value")
      .bind(1, key)
      .bind(2, value)
      .run();
}

std::string MatchStore::serverId() {
  return readMeta("server_id");
}

protocol::KeyPair MatchStore::serverKey() {
  {
    auto q = db_.prepare("SELECT secret_key FROM server_key WHERE id = 1");
    if (q.step()) {
      auto pair = protocol::keyPairFromSecret(q.blob(0), "the server key kept in the database");
      if (!pair) throw StoreError(pair.error());
      return *pair;
    }
  }
  const protocol::KeyPair pair = protocol::generateKeyPair();
  Transaction made(db_);
  db_.prepare("INSERT INTO server_key(id, secret_key, created) VALUES(1, ?, strftime('%s'))")
      .bindBlob(1, pair.secret_key)
      .run();
  made.commit();
  return pair;
}

std::uint64_t MatchStore::opened() {
  const std::string text = readMeta("opened");
  return text.empty() ? 0 : std::strtoull(text.c_str(), nullptr, 10);
}

// ---- Writing ------------------------------------------------------------------------------------

void MatchStore::writeMatch(const server::MatchSnapshot& m) {
  db_.prepare(std::string("INSERT OR REPLACE INTO matches(") + kMatchColumns +
              ") VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, m.id)
      .bind(2, i64(m.number))
      .bind(3, m.name)
      .bind(4, rules::tableOf(m.settings.game, table_))
      .bind(5, i64(m.rack_seed))
      .bind(6, i64(m.layouts))
      .bind(7, std::int64_t{m.started})
      .bind(8, std::int64_t{m.closed})
      .bind(9, std::int64_t{m.client_made})
      .bind(10, std::int64_t{m.shot_number})
      .bind(11, std::int64_t{m.rack})
      .bind(12, i64(m.revision))
      .bind(13, m.last_verdict)
      .bind(14, gameJson(m.game))
      .bind(15, ballsJson(m.balls))
      .bind(16, settingsJson(m.settings))
      .bind(17, std::int64_t{static_cast<int>(m.rack_generator)})
      .run();
  auto seat = db_.prepare(
      "INSERT OR REPLACE INTO seats(match, seat, player, token, client, last_seq, fouls, "
      "racks_won, wants_rematch, public_key) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < 2; ++i) {
    const server::Seat& s = m.seats[i];
    seat.bind(1, m.id)
        .bind(2, static_cast<std::int64_t>(i))
        .bind(3, s.player)
        .bind(4, i64(s.token))
        .bind(5, s.client)
        .bind(6, std::int64_t{s.last_seq})
        .bind(7, std::int64_t{s.fouls})
        .bind(8, std::int64_t{s.racks_won})
        .bind(9, std::int64_t{s.wants_rematch})
        .bindBlob(10, s.public_key)
        .run();
    seat.reset();
  }
  // A decided match is rated with the write that stores its decision (once: rateDecided).
  rateDecided(db_, m);
}

void MatchStore::saveMatches(const std::string& server_id, std::uint64_t opened,
                             const std::vector<server::MatchSnapshot>& matches) {
  Transaction tx(db_);
  writeMeta("server_id", server_id);
  writeMeta("opened", std::to_string(opened));
  for (const auto& m : matches) writeMatch(m);
  tx.commit();
  checkStillThere();
}

void MatchStore::closeMatch(const std::string& id) {
  db_.prepare("UPDATE matches SET closed = 1 WHERE id = ?").bind(1, id).run();
  checkStillThere();
}

void MatchStore::checkStillThere() {
  const auto still = watch_.check();
  if (still) return;
  throw StoreError(still.error() + ": stopping; " + rescue());
}

std::string MatchStore::rescue() {
  const std::string& path = watch_.path();
  std::error_code ec;
  std::string target = path;
  if (std::filesystem::exists(path, ec)) {
    // Replaced by someone's file: never overwrite it.
    target = path + ".rescued-" + std::to_string(std::time(nullptr));
  }
  // The folder may still be going as we save (a recursive delete takes the file first, then the
  // folder): it is made again before each try, and a try it lost is made once more.
  const auto folder = std::filesystem::path(path).parent_path();
  auto done = Result<BackupDone>::fail("not tried");
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (!folder.empty()) std::filesystem::create_directories(folder, ec);
    done = backupTo(db_, target);
    if (done || std::filesystem::is_directory(folder, ec)) break;
  }
  if (!done) {
    return "the open database could not be saved (" + done.error() +
           "): what was stored since the file went is lost with the process";
  }
  return "everything stored, the last accepted shot included, is saved in " + target +
         " (start the server on it)";
}

void MatchStore::recordShot(const server::ShotRecord& r, const std::string& verdict_text,
                            const server::MatchSnapshot& after) {
  Transaction tx(db_);
  writeMatch(after);
  db_.prepare(
         "INSERT INTO shots(match, shot_number, shoots, seat, seq, command, state, before, intent, "
         "events, after, verdict, verdict_text) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, after.id)
      .bind(2, std::int64_t{r.shot_number})
      .bind(3, std::int64_t{r.shoots})
      .bind(4, std::int64_t{r.command.seat})
      .bind(5, std::int64_t{r.command.seq})
      .bind(6, commandJson(r.command))
      .bind(7, gameJson(r.state))
      .bind(8, ballsJson(r.before))
      .bind(9, intentJson(r.intent))
      .bind(10, eventsJson(r.events))
      .bind(11, ballsJson(r.after))
      .bind(12, verdictJson(r.verdict))
      .bind(13, verdict_text)
      .run();
  countStroke(db_, r, after);
  tx.commit();
  checkStillThere();
}

// ---- Reading ------------------------------------------------------------------------------------

std::vector<server::MatchSnapshot> MatchStore::matches() {
  std::vector<server::MatchSnapshot> out;
  auto q = db_.prepare(std::string("SELECT ") + kMatchColumns + " FROM matches ORDER BY number");
  while (q.step()) out.push_back(matchAt(q));
  auto seats = db_.prepare(
      "SELECT seat, player, token, client, last_seq, fouls, racks_won, wants_rematch, public_key "
      "FROM seats WHERE match = ?");
  for (auto& m : out) {
    seats.bind(1, m.id);
    while (seats.step()) {
      const auto i = seats.integer(0);
      if (i != 0 && i != 1)
        throw StoreError("match " + m.id + ": a seat numbered " + std::to_string(i));
      server::Seat& s = m.seats[static_cast<std::size_t>(i)];
      s.player = seats.text(1);
      s.token = u64(seats.integer(2));
      s.client = seats.text(3);
      s.last_seq = static_cast<std::uint32_t>(seats.integer(4));
      s.fouls = static_cast<int>(seats.integer(5));
      s.racks_won = static_cast<int>(seats.integer(6));
      s.wants_rematch = seats.integer(7) != 0;
      s.public_key = seats.blob(8);
    }
    seats.reset();
  }
  return out;
}

std::optional<server::MatchSnapshot> MatchStore::match(const std::string& id) {
  for (auto& m : matches()) {
    if (m.id == id) return m;
  }
  return std::nullopt;
}

std::optional<MatchStore::MatchHeader> MatchStore::header(const std::string& id) {
  auto q = db_.prepare("SELECT settings FROM matches WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  MatchHeader h;
  h.settings = settingsFrom(q.text(0));
  auto seats = db_.prepare("SELECT seat, player FROM seats WHERE match = ?");
  seats.bind(1, id);
  while (seats.step()) {
    const auto seat = seats.integer(0);
    if (seat == 0 || seat == 1) h.players[static_cast<std::size_t>(seat)] = seats.text(1);
  }
  return h;
}

std::string MatchStore::tableOf(const std::string& id) {
  auto q = db_.prepare("SELECT table_name FROM matches WHERE id = ?");
  q.bind(1, id);
  return q.step() ? q.text(0) : std::string();
}

namespace {

constexpr const char* kShotColumns =
    "SELECT shot_number, shoots, command, state, before, intent, events, after, verdict, "
    "verdict_text FROM shots ";

/// The stored shot of the row `q` stands on (its columns as kShotColumns lists them).
StoredShot shotOfRow(Statement& q, const std::string& match) {
  StoredShot s;
  s.match = match;
  s.record.shot_number = static_cast<std::uint32_t>(q.integer(0));
  s.record.shoots = q.integer(1) != 0;
  s.record.command = commandFrom(q.text(2));
  s.record.state = gameFrom(q.text(3));
  s.record.before = ballsFrom(q.text(4));
  s.record.intent = intentFrom(q.text(5));
  s.record.events = eventsFrom(q.text(6));
  s.record.after = ballsFrom(q.text(7));
  s.record.verdict = verdictFrom(q.text(8));
  s.verdict_text = q.text(9);
  return s;
}

}  // namespace

std::vector<StoredShot> MatchStore::shots(const std::string& id) {
  std::vector<StoredShot> out;
  auto q = db_.prepare(std::string(kShotColumns) + "WHERE match = ? ORDER BY id");
  q.bind(1, id);
  while (q.step()) out.push_back(shotOfRow(q, id));
  return out;
}

std::optional<StoredShot> MatchStore::stroke(const std::string& id, std::uint32_t number) {
  auto q = db_.prepare(std::string(kShotColumns) +
                       "WHERE match = ? AND shot_number = ? AND shoots = 1 ORDER BY id LIMIT 1");
  q.bind(1, id);
  q.bind(2, static_cast<std::int64_t>(number));
  if (!q.step()) return std::nullopt;
  return shotOfRow(q, id);
}

std::uint32_t MatchStore::strokes(const std::string& id) {
  auto q =
      db_.prepare("SELECT COALESCE(MAX(shot_number), 0) FROM shots WHERE match = ? AND shoots = 1");
  q.bind(1, id);
  return q.step() ? static_cast<std::uint32_t>(q.integer(0)) : 0;
}

}  // namespace pool::store
