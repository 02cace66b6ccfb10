// Banned keys: one row each in the bans table (schema version 3).
#include "server/store/ban_list.h"

namespace pool::store {

bool addBan(Database& db, const std::vector<std::uint8_t>& key, const std::string& reason) {
  auto insert = db.prepare(
      "INSERT OR IGNORE INTO bans(public_key, reason, banned_at) "
      "VALUES(?, ?, datetime('now'))");
  insert.bindBlob(1, key).bind(2, reason).run();
  return db.integer("SELECT changes()") > 0;
}

bool removeBan(Database& db, const std::vector<std::uint8_t>& key) {
  db.prepare("DELETE FROM bans WHERE public_key = ?").bindBlob(1, key).run();
  return db.integer("SELECT changes()") > 0;
}

std::vector<Ban> bans(Database& db) {
  std::vector<Ban> out;
  auto rows = db.prepare("SELECT public_key, reason, banned_at FROM bans ORDER BY rowid");
  while (rows.step()) out.push_back({rows.blob(0), rows.text(1), rows.text(2)});
  return out;
}

}  // namespace pool::store
