// Tournaments in a real SQLite file: saved and read back field by field, replaced by id, listed
// by number, the counter of tournaments opened, kept across a reopen, and a schema-8 file
// migrated to 9 with its data.
#include <gtest/gtest.h>

#include "server/store/ban_list.h"
#include "server/store/match_store.h"
#include "server/store/schema.h"
#include "server/store/tournament_book.h"
#include "store_fixture.h"

namespace pool::store {
namespace {

using test::Scratch;

StoredTournament sample(const std::string& id, std::uint64_t number) {
  return StoredTournament{
      .id = id,
      .number = number,
      .name = "Spring Open — Zoë's",
      .format = 1,
      .game = 9,
      .race_to = 5,
      .capacity = 16,
      .phase = 2,
      .entries = R"([{"id":"ab","name":"Ann","rating":1612.5}])",
      .state = R"({"format":1,"matches":[]})",
      .match_ids = R"(["srv-4",""])",
      .created = 1'700'000'123,
      .options = R"({"handicap":true,"opened_by":"Zoë"})",
  };
}

void expectSame(const StoredTournament& got, const StoredTournament& want) {
  EXPECT_EQ(got.id, want.id);
  EXPECT_EQ(got.number, want.number);
  EXPECT_EQ(got.name, want.name);
  EXPECT_EQ(got.format, want.format);
  EXPECT_EQ(got.game, want.game);
  EXPECT_EQ(got.race_to, want.race_to);
  EXPECT_EQ(got.capacity, want.capacity);
  EXPECT_EQ(got.phase, want.phase);
  EXPECT_EQ(got.entries, want.entries);
  EXPECT_EQ(got.state, want.state);
  EXPECT_EQ(got.match_ids, want.match_ids);
  EXPECT_EQ(got.created, want.created);
  EXPECT_EQ(got.options, want.options);
}

TEST(TournamentBook, ASavedTournamentReadsBackEveryField) {
  Scratch scratch;
  const std::string path = scratch.file("pool.db");
  const StoredTournament t = sample("srv-t1", 1);
  {
    auto store = MatchStore::open(path);
    ASSERT_TRUE(store) << store.error();
    Database& db = (*store)->database();
    EXPECT_TRUE(tournaments(db).empty());
    EXPECT_FALSE(tournament(db, "srv-t1"));
    saveTournament(db, t);
    const auto got = tournament(db, "srv-t1");
    ASSERT_TRUE(got);
    expectSame(*got, t);
    EXPECT_FALSE(tournament(db, "srv-t2"));
  }
  // Kept in the file: a reopened store reads it the same.
  auto store = MatchStore::open(path);
  ASSERT_TRUE(store) << store.error();
  const auto got = tournament((*store)->database(), "srv-t1");
  ASSERT_TRUE(got);
  expectSame(*got, t);
}

TEST(TournamentBook, ATournamentBeforeItsStartHasAnEmptyState) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  Database& db = (*store)->database();
  StoredTournament t{.id = "srv-t1", .number = 1, .name = "Open", .capacity = 8};
  t.entries = "[]";
  t.match_ids = "[]";
  saveTournament(db, t);
  const auto got = tournament(db, "srv-t1");
  ASSERT_TRUE(got);
  EXPECT_TRUE(got->state.empty());
  EXPECT_EQ(got->race_to, 1);
  EXPECT_EQ(got->entries, "[]");
}

TEST(TournamentBook, SavingAgainReplacesTheTournamentOfThatId) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  Database& db = (*store)->database();
  StoredTournament t = sample("srv-t1", 1);
  t.phase = 0;
  t.state.clear();
  saveTournament(db, t);
  t.phase = 3;
  t.state = R"({"format":1,"matches":[{"id":0}]})";
  t.match_ids = R"(["srv-4","srv-5"])";
  saveTournament(db, t);
  const auto all = tournaments(db);
  ASSERT_EQ(all.size(), 1u);
  expectSame(all[0], t);
}

TEST(TournamentBook, TournamentsAreListedByNumberAndCounted) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  Database& db = (*store)->database();
  EXPECT_EQ(tournamentsOpened(db), 0u);
  // Saved out of order, ids not in number order either.
  saveTournament(db, sample("srv-t10", 10));
  saveTournament(db, sample("srv-t2", 2));
  saveTournament(db, sample("srv-t7", 7));
  const auto all = tournaments(db);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].id, "srv-t2");
  EXPECT_EQ(all[1].id, "srv-t7");
  EXPECT_EQ(all[2].id, "srv-t10");
  EXPECT_EQ(all[0].number, 2u);
  EXPECT_EQ(all[2].number, 10u);
  EXPECT_EQ(tournamentsOpened(db), 10u);
}

/// A file of schema `version` (its first `version` steps, as that version ran them) with `data`
/// of its own, written at `path`.
void writeFileOfSchema(const std::string& path, std::size_t version, const std::string& data) {
  std::string sql;
  const auto steps = migrationSteps();
  ASSERT_GT(steps.size(), version);
  for (std::size_t i = 0; i < version; ++i) sql += steps[i];
  sql += data +
         "PRAGMA application_id = 1347374924;\nPRAGMA user_version = " + std::to_string(version) +
         ";\n";
  test::runSql(path, sql);
}

TEST(TournamentBook, ATournamentOfSchemaNineReadsWithNoOptions) {
  Scratch scratch;
  const std::string path = scratch.file("v9.db");
  ASSERT_NO_FATAL_FAILURE(writeFileOfSchema(path, 9, R"sql(
INSERT INTO meta VALUES('server_id', 'old'), ('opened', '0');
INSERT INTO tournaments VALUES('old-t1', 1, 'Cup', 0, 8, 2, 4, 0, '[]', '', '[]', 17);
)sql"));
  auto store = MatchStore::open(path);
  ASSERT_TRUE(store) << store.error();
  const auto got = tournament((*store)->database(), "old-t1");
  ASSERT_TRUE(got);
  EXPECT_EQ(got->name, "Cup");
  EXPECT_EQ(got->race_to, 2);
  EXPECT_EQ(got->options, "{}") << "an operator's tournament without a handicap";
}

TEST(TournamentBook, AFileOfSchemaEightMigratesToNineKeepingItsData) {
  Scratch scratch;
  const std::string path = scratch.file("v8.db");
  ASSERT_NO_FATAL_FAILURE(writeFileOfSchema(path, 8, R"sql(
INSERT INTO meta VALUES('server_id', 'old'), ('opened', '4');
INSERT INTO bans VALUES(x'0102', 'spam', '2024-01-02 03:04:05');
)sql"));
  auto store = MatchStore::open(path);
  ASSERT_TRUE(store) << store.error();
  Database& db = (*store)->database();
  EXPECT_EQ(db.integer("PRAGMA user_version"), kSchemaVersion);
  EXPECT_EQ(kSchemaVersion, 10);
  EXPECT_EQ((*store)->serverId(), "old");
  EXPECT_EQ((*store)->opened(), 4u);
  const auto kept = bans(db);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].reason, "spam");
  // Version 9's table, empty, takes tournaments from now on.
  EXPECT_TRUE(tournaments(db).empty());
  EXPECT_EQ(tournamentsOpened(db), 0u);
  saveTournament(db, sample("old-t1", 1));
  ASSERT_TRUE(tournament(db, "old-t1"));
  EXPECT_EQ(tournamentsOpened(db), 1u);
}

}  // namespace
}  // namespace pool::store
