// The server's SQLite file: its id and match counter, every match, and every accepted command.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "protocol/key_pair.h"
#include "protocol/match_settings.h"
#include "server/match/match_snapshot.h"
#include "server/match/shot_record.h"
#include "server/store/file_watch.h"
#include "server/store/sqlite_db.h"

namespace pool::store {

/// One stored command with the match it belongs to.
struct StoredShot {
  std::string match;
  server::ShotRecord record;
  std::string verdict_text;
};

/// A match a restarted server picks up: not closed, with someone seated (a match that is over is
/// kept for its players, who may ask for a rematch, as a running server keeps it).
bool resumable(const server::MatchSnapshot& match);

/// The store. Writes throw StoreError (the file went bad under us: the caller stops rather than
/// publish what is not stored).
class MatchStore {
 public:
  /// Opens the file at `path` (created with its folder when missing) and migrates it forward.
  /// Refuses a file that is not SQLite, truncated, failing quick_check, not a pool database, or
  /// of a newer schema, without writing to it: the reason is "<path>: <why>".
  static Result<std::unique_ptr<MatchStore>> open(const std::string& path);

  /// The table spec the matches written from now on are played on.
  void setTable(std::string table) { table_ = std::move(table); }

  /// The server id kept in the file; empty when none yet.
  std::string serverId();
  /// The server's own key pair, which signs everything it publishes: made and kept the first
  /// time, the same for the life of the file. Throws StoreError when the kept key is unreadable.
  protocol::KeyPair serverKey();
  /// The number of matches opened so far (ids are never reused).
  std::uint64_t opened();

  /// Saves the server id, the counter and `matches` (with their seats) in one transaction.
  void saveMatches(const std::string& server_id, std::uint64_t opened,
                   const std::vector<server::MatchSnapshot>& matches);
  /// Marks match `id` closed (a client-made match nobody uses any more).
  void closeMatch(const std::string& id);
  /// Stores an accepted command and the match as it left it (at rest), in one transaction, so the
  /// result may then be published.
  void recordShot(const server::ShotRecord& record, const std::string& verdict_text,
                  const server::MatchSnapshot& after);

  /// Every stored match, oldest first.
  std::vector<server::MatchSnapshot> matches();
  /// The stored match `id`.
  std::optional<server::MatchSnapshot> match(const std::string& id);
  /// What a replay names of stored match `id` (one indexed lookup, its seats aside): its
  /// settings and its seated players' names; empty when no such match.
  struct MatchHeader {
    protocol::MatchSettings settings;
    std::array<std::string, 2> players;
  };
  std::optional<MatchHeader> header(const std::string& id);
  /// The table spec match `id` is played on (empty when no such match).
  std::string tableOf(const std::string& id);
  /// Every stored command of match `id`, in the order they were accepted.
  std::vector<StoredShot> shots(const std::string& id);
  /// The stroke numbered `number` of match `id` (a choice keeps the number of the stroke before
  /// it, and is not one), if stored.
  std::optional<StoredShot> stroke(const std::string& id, std::uint32_t number);
  /// The number of match `id`'s last stored stroke (0: none).
  std::uint32_t strokes(const std::string& id);

  Database& database() { return db_; }

  /// Throws StoreError when the file was deleted (or its folder) or replaced since it was opened,
  /// after saving what the open connection still holds (everything committed, the last write
  /// included) where a restart finds it: at the file's own path when nothing is there (its
  /// folder made again), else beside the file that replaced it ("<path>.rescued-<time>"). Every
  /// write calls it after its commit; the server also calls it about once a second.
  void checkStillThere();

 private:
  MatchStore(Database db, const std::string& path) : db_(std::move(db)), watch_(path) {}
  /// Saves the open database for a restart (see checkStillThere); says where, or why not.
  std::string rescue();
  void writeMatch(const server::MatchSnapshot& match);
  void writeMeta(const std::string& key, const std::string& value);
  std::string readMeta(const std::string& key);

  Database db_;
  FileWatch watch_;
  std::string table_ = "wpa-9ft";
};

/// $XDG_DATA_HOME/pool/pool.db, else ~/.local/share/pool/pool.db (the folder may not exist yet).
std::string defaultDbPath();

}  // namespace pool::store
