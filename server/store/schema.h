// The store's schema: its version, the forward migrations, and the checks before a file is used.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "core/check.h"
#include "server/store/sqlite_db.h"

namespace pool::store {

/// The schema version this code writes (PRAGMA user_version).
inline constexpr int kSchemaVersion = 10;
/// PRAGMA application_id of a pool database ("POOL").
inline constexpr std::int64_t kApplicationId = 0x504F4F4C;

/// The migration steps: steps()[v] takes a file from version v to v + 1 (0: an empty file).
std::span<const char* const> migrationSteps();

/// Checks an existing file without writing to it: an SQLite file, not truncated, passing
/// PRAGMA quick_check, a pool database (or an empty one), of a version this code knows.
/// Refuses it with the reason (one line).
Check<> checkFile(const std::string& path);

/// Runs the steps from the file's version up to kSchemaVersion, one transaction each.
void migrate(Database& db);

}  // namespace pool::store
