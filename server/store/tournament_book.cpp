// Tournaments in the store: one row each in the tournaments table (schema version 9; options
// since 10).
#include "server/store/tournament_book.h"

namespace pool::store {

namespace {

constexpr const char* kTournamentColumns =
    "id, number, name, format, game, race_to, capacity, phase, entries, state, match_ids, "
    "created, options";

int tournamentInt(const Statement& q, int column) {
  return static_cast<int>(q.integer(column));
}

StoredTournament tournamentAt(const Statement& q) {
  StoredTournament t;
  t.id = q.text(0);
  t.number = static_cast<std::uint64_t>(q.integer(1));
  t.name = q.text(2);
  t.format = tournamentInt(q, 3);
  t.game = tournamentInt(q, 4);
  t.race_to = tournamentInt(q, 5);
  t.capacity = tournamentInt(q, 6);
  t.phase = tournamentInt(q, 7);
  t.entries = q.text(8);
  t.state = q.text(9);
  t.match_ids = q.text(10);
  t.created = q.integer(11);
  t.options = q.text(12);
  return t;
}

}  // namespace

void saveTournament(Database& db, const StoredTournament& t) {
  Transaction tx(db);
  db.prepare(std::string("INSERT OR REPLACE INTO tournaments(") + kTournamentColumns +
             ") VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, t.id)
      .bind(2, static_cast<std::int64_t>(t.number))
      .bind(3, t.name)
      .bind(4, std::int64_t{t.format})
      .bind(5, std::int64_t{t.game})
      .bind(6, std::int64_t{t.race_to})
      .bind(7, std::int64_t{t.capacity})
      .bind(8, std::int64_t{t.phase})
      .bind(9, t.entries)
      .bind(10, t.state)
      .bind(11, t.match_ids)
      .bind(12, t.created)
      .bind(13, t.options)
      .run();
  tx.commit();
}

std::vector<StoredTournament> tournaments(Database& db) {
  std::vector<StoredTournament> out;
  auto q =
      db.prepare(std::string("SELECT ") + kTournamentColumns + " FROM tournaments ORDER BY number");
  while (q.step()) out.push_back(tournamentAt(q));
  return out;
}

std::optional<StoredTournament> tournament(Database& db, const std::string& id) {
  auto q =
      db.prepare(std::string("SELECT ") + kTournamentColumns + " FROM tournaments WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return tournamentAt(q);
}

std::uint64_t tournamentsOpened(Database& db) {
  return static_cast<std::uint64_t>(db.integer("SELECT coalesce(max(number), 0) FROM tournaments"));
}

}  // namespace pool::store
