// A copy of the open database to another file while the server keeps its lock (SQLite's backup
// API).
#pragma once

#include <string>

#include "core/result.h"
#include "server/store/sqlite_db.h"

namespace pool::store {

/// What a backup wrote.
struct BackupDone {
  std::string path;
  std::int64_t pages = 0;
  std::int64_t bytes = 0;
};

/// Copies every page of `db` (the server's own connection, so its exclusive lock is no obstacle)
/// to a new file at `path`, through "<path>.partial" renamed once complete: a file at `path` is
/// never half written. Refused without writing anything: a relative path, a folder that does not
/// exist, a file already at `path` (nothing is overwritten). The reason is one line.
Result<BackupDone> backupTo(Database& db, const std::string& path);

}  // namespace pool::store
