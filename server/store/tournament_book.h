// The tournaments the store keeps (schema 9, options since 10): one row each, its settings and its
// texts opaque.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "server/store/sqlite_db.h"

namespace pool::store {

/// One tournament as stored. The store checks none of it: the texts are the server's.
struct StoredTournament {
  std::string id = {};         ///< the tournament's id (the row's key)
  std::uint64_t number = 0;    ///< its number on this server, from 1 (the tournaments opened)
  std::string name = {};       ///< shown to the players
  int format = 0;              ///< pool_tournament's Format as a number
  int game = 0;                ///< the game's number (rules::gameNumber)
  int race_to = 1;             ///< each match a race to this many racks
  int capacity = 0;            ///< the entrants it takes
  int phase = 0;               ///< the server's phase of it (taking entries, running, over, ...)
  std::string entries = {};    ///< JSON: the entries taken before the start
  std::string state = {};      ///< pool_tournament's Tournament::toJson(); empty before the start
  std::string match_ids = {};  ///< JSON array: the server match id of each match index, or ""
  std::int64_t created = 0;    ///< when it was created (the server's clock, seconds)
  std::string options = "{}";  ///< JSON: the handicap, who opened it (since schema 10)
};

/// Stores `t`, replacing the tournament of the same id, in a transaction of its own. Throws
/// StoreError. Nothing after the commit: the caller checks the file is still there.
void saveTournament(Database& db, const StoredTournament& t);

/// Every stored tournament, by number.
std::vector<StoredTournament> tournaments(Database& db);

/// The stored tournament `id`; empty when there is none.
std::optional<StoredTournament> tournament(Database& db, const std::string& id);

/// The highest tournament number stored (the counter of tournaments opened); 0 when none.
std::uint64_t tournamentsOpened(Database& db);

}  // namespace pool::store
