// The public keys an operator banned from the server, kept in the store's file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "server/store/sqlite_db.h"

namespace pool::store {

/// One banned key.
struct Ban {
  std::vector<std::uint8_t> public_key;
  std::string reason;
  std::string banned_at;  ///< UTC, "YYYY-MM-DD HH:MM:SS"
};

/// Adds `key` to the bans with `reason` (a key banned already keeps its first reason); true when
/// it was not banned before. Throws StoreError.
bool addBan(Database& db, const std::vector<std::uint8_t>& key, const std::string& reason);
/// Removes `key` from the bans; true when it was banned. Throws StoreError.
bool removeBan(Database& db, const std::vector<std::uint8_t>& key);
/// Every banned key, oldest ban first.
std::vector<Ban> bans(Database& db);

}  // namespace pool::store
