// sqlite3_backup from the server's connection into a fresh file, renamed into place when complete.
#include "server/store/online_backup.h"

#include <sqlite3.h>

#include <filesystem>

#include "core/check.h"

namespace pool::store {

namespace {

namespace fs = std::filesystem;

/// Refuses a `path` that cannot receive a backup, with why.
Check<> checkTarget(const fs::path& path) {
  if (!path.is_absolute()) return Check<>::refuse("not_absolute", "must be an absolute path");
  if (!path.has_filename()) return Check<>::refuse("not_a_file", "names a folder, not a file");
  std::error_code ec;
  const fs::path folder = path.parent_path();
  if (!fs::is_directory(folder, ec))
    return Check<>::refuse("no_folder", "folder " + folder.string() + " does not exist");
  if (fs::exists(fs::symlink_status(path, ec)))
    return Check<>::refuse("file_exists", "a file is there already (not overwritten)");
  if (fs::exists(fs::symlink_status(path.string() + ".partial", ec))) {
    return Check<>::refuse("backup_running",
                           path.string() + ".partial is there already (another backup running?)");
  }
  return Check<>::pass();
}

}  // namespace

Result<BackupDone> backupTo(Database& db, const std::string& path) {
  const fs::path target(path);
  if (auto ok = checkTarget(target); !ok)
    return Result<BackupDone>::fail(ok.code(), path + ": " + ok.error());
  const std::string partial = path + ".partial";
  sqlite3* out = nullptr;
  const int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOFOLLOW;
  std::string error;
  if (sqlite3_open_v2(partial.c_str(), &out, flags, nullptr) != SQLITE_OK) {
    error = out ? sqlite3_errmsg(out) : "cannot open";
  } else if (sqlite3_backup* copy = sqlite3_backup_init(out, "main", db.handle(), "main")) {
    const int rc = sqlite3_backup_step(copy, -1);  // every page in one step
    sqlite3_backup_finish(copy);
    if (rc != SQLITE_DONE) error = sqlite3_errstr(rc);
  } else {
    error = sqlite3_errmsg(out);
  }
  BackupDone done;
  if (error.empty()) {
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(out, "PRAGMA page_count", -1, &stmt, nullptr) == SQLITE_OK &&
        sqlite3_step(stmt) == SQLITE_ROW) {
      done.pages = sqlite3_column_int64(stmt, 0);
    }
    sqlite3_finalize(stmt);
  }
  sqlite3_close(out);
  std::error_code ec;
  if (error.empty()) {
    fs::rename(partial, target, ec);
    if (ec) error = "rename from " + partial + ": " + ec.message();
  }
  if (!error.empty()) {
    fs::remove(partial, ec);
    fs::remove(partial + "-wal", ec);
    fs::remove(partial + "-shm", ec);
    fs::remove(partial + "-journal", ec);
    return Result<BackupDone>::fail(path + ": " + error);
  }
  done.path = path;
  done.bytes = static_cast<std::int64_t>(fs::file_size(target, ec));
  return Result<BackupDone>::ok(done);
}

}  // namespace pool::store
