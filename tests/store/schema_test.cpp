// The schema: fresh files, a version-1 file made by hand migrated forward, and the files refused
// untouched (not SQLite, truncated, failing quick_check, another program's, a newer schema).
#include <gtest/gtest.h>

#include <filesystem>

#include "server/server_process.h"
#include "server/store/match_store.h"
#include "server/store/schema.h"
#include "store_fixture.h"

namespace pool::store::test {
namespace {

// The version-1 schema as that version wrote it, typed here by hand (not taken from the code).
constexpr const char* kVersionOneFile = R"sql(
CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE matches(
  id TEXT PRIMARY KEY, number INTEGER NOT NULL, name TEXT NOT NULL, table_name TEXT NOT NULL,
  rack_seed INTEGER NOT NULL, layouts INTEGER NOT NULL, started INTEGER NOT NULL,
  closed INTEGER NOT NULL, client_made INTEGER NOT NULL, shot_number INTEGER NOT NULL,
  rack INTEGER NOT NULL, revision INTEGER NOT NULL, last_verdict TEXT NOT NULL,
  game TEXT NOT NULL, balls TEXT NOT NULL);
CREATE TABLE seats(
  match TEXT NOT NULL REFERENCES matches(id), seat INTEGER NOT NULL, player TEXT NOT NULL,
  token INTEGER NOT NULL, client TEXT NOT NULL, last_seq INTEGER NOT NULL,
  fouls INTEGER NOT NULL, racks_won INTEGER NOT NULL, wants_rematch INTEGER NOT NULL,
  PRIMARY KEY(match, seat));
CREATE TABLE shots(
  id INTEGER PRIMARY KEY, match TEXT NOT NULL REFERENCES matches(id),
  shot_number INTEGER NOT NULL, shoots INTEGER NOT NULL, seat INTEGER NOT NULL,
  seq INTEGER NOT NULL, command TEXT NOT NULL, state TEXT NOT NULL, before TEXT NOT NULL,
  intent TEXT NOT NULL, events TEXT NOT NULL, after TEXT NOT NULL, verdict TEXT NOT NULL,
  verdict_text TEXT NOT NULL);
CREATE INDEX shots_of_match ON shots(match, shot_number);
INSERT INTO meta VALUES('server_id', 'old'), ('opened', '7');
INSERT INTO matches VALUES('old-7', 7, 'Corner table', 'wpa-9ft', 99, 1, 1, 0, 0, 3, 1, 12, '',
  '{"phase":1,"shooter":1,"breaker":0,"groups":[0,0],"ball_in_hand":0,"options":[],"dry_turns":2,"winner":-1,"end":0}',
  '[{"id":0,"pos":[-0.5,0.25,0.028575],"q":[1,0,0,0],"vel":[0,0,0],"w":[0,0,0],"state":0,"pocket":""}]');
INSERT INTO seats VALUES('old-7', 0, 'Ada', 4660, 'client-a', 2, 0, 0, 0);
INSERT INTO seats VALUES('old-7', 1, 'Bob', 22136, 'client-b', 1, 1, 0, 0);
PRAGMA application_id = 1347374924;
PRAGMA user_version = 1;
)sql";

/// A pool database of the current version with one match.
std::string validFile(const Scratch& scratch, const std::string& name) {
  const std::string path = scratch.file(name);
  {
    auto store = MatchStore::open(path);
    EXPECT_TRUE(store) << store.error();
    server::MatchSnapshot m;
    m.id = "srv-1";
    m.number = 1;
    m.name = "Table 1";
    m.seats[0].player = "Ada";
    m.seats[0].token = 77;
    (*store)->saveMatches("srv", 1, {m});
  }
  // Folded back into the main file: the file alone is the whole database.
  runSql(path, "PRAGMA wal_checkpoint(TRUNCATE); PRAGMA journal_mode = DELETE;");
  return path;
}

/// Opening `path` is refused with one line naming it, and the file keeps every byte.
void expectRefused(const std::string& path, const std::string& why) {
  const std::string before = bytesOf(path);
  auto store = MatchStore::open(path);
  ASSERT_FALSE(store) << "opened a file that is " << why;
  EXPECT_EQ(store.error().rfind(path + ": ", 0), 0u) << store.error();
  EXPECT_NE(store.error().find(why), std::string::npos) << store.error();
  EXPECT_EQ(store.error().find('\n'), std::string::npos) << store.error();
  EXPECT_EQ(hashOf(bytesOf(path)), hashOf(before)) << "the refused file changed";
  EXPECT_EQ(bytesOf(path).size(), before.size());
}

TEST(SchemaTest, AFreshFileIsCreatedWithItsFolderAtTheCurrentVersion) {
  Scratch scratch;
  const std::string path = scratch.file("deep/er/pool.db");
  auto store = MatchStore::open(path);
  ASSERT_TRUE(store) << store.error();
  EXPECT_EQ((*store)->database().integer("PRAGMA user_version"), kSchemaVersion);
  EXPECT_EQ((*store)->database().integer("PRAGMA application_id"), kApplicationId);
  EXPECT_EQ(migrationSteps().size(), static_cast<std::size_t>(kSchemaVersion));
  EXPECT_TRUE((*store)->serverId().empty());
  EXPECT_EQ((*store)->opened(), 0u);
}

TEST(SchemaTest, AVersionOneFileMadeByHandOpensMigratedWithItsMatches) {
  Scratch scratch;
  const std::string path = scratch.file("v1.db");
  runSql(path, kVersionOneFile);
  auto store = MatchStore::open(path);
  ASSERT_TRUE(store) << store.error();
  EXPECT_EQ((*store)->database().integer("PRAGMA user_version"), kSchemaVersion);
  EXPECT_EQ((*store)->serverId(), "old");
  EXPECT_EQ((*store)->opened(), 7u);
  const auto m = (*store)->match("old-7");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->name, "Corner table");
  EXPECT_EQ(m->shot_number, 3u);
  EXPECT_EQ(m->game.shooter, 1);
  EXPECT_EQ(m->game.dry_turns, 2);
  ASSERT_EQ(m->balls.size(), 1u);
  EXPECT_DOUBLE_EQ(m->balls[0].pos.y(), 0.25);
  EXPECT_EQ(m->seats[0].token, 4660u);
  EXPECT_EQ(m->seats[1].player, "Bob");
  EXPECT_EQ(m->seats[1].fouls, 1);
  EXPECT_TRUE(m->seats[0].public_key.empty());  // the column version 2 added
  // Version 6: a match stored before racks had gaps goes on racking frozen triangles.
  EXPECT_EQ(m->rack_generator, table::RackGenerator::Frozen);

  // Version 2's column takes a key from now on.
  auto changed = *m;
  changed.seats[0].public_key = {1, 2, 3, 0, 255};
  (*store)->saveMatches("old", 7, {changed});
  EXPECT_EQ((*store)->match("old-7")->seats[0].public_key, changed.seats[0].public_key);
}

TEST(SchemaTest, AFileThatIsNotSqliteIsRefusedUntouched) {
  Scratch scratch;
  const std::string path = scratch.file("notes.db");
  writeBytes(path, std::string(4096, 'x') + "not a database at all\n");
  expectRefused(path, "not an SQLite database");
}

TEST(SchemaTest, ATruncatedFileIsRefusedUntouched) {
  Scratch scratch;
  const std::string path = validFile(scratch, "cut.db");
  const std::string whole = bytesOf(path);
  ASSERT_GT(whole.size(), 4096u);
  writeBytes(path, whole.substr(0, whole.size() / 2));
  expectRefused(path, "truncated");
}

TEST(SchemaTest, AFileFailingQuickCheckIsRefusedUntouched) {
  Scratch scratch;
  const std::string path = validFile(scratch, "bad.db");
  std::string bytes = bytesOf(path);
  const std::size_t page = 4096;
  ASSERT_GE(bytes.size(), 3 * page);
  // Page 2 is a table's b-tree page: an unknown page type breaks it.
  bytes[page] = static_cast<char>(0x77);
  bytes[page + 3] = static_cast<char>(0x7f);
  writeBytes(path, bytes);
  expectRefused(path, "integrity check");
}

TEST(SchemaTest, AFileOfANewerSchemaIsRefusedUntouched) {
  Scratch scratch;
  const std::string path = validFile(scratch, "newer.db");
  runSql(path, "PRAGMA user_version = " + std::to_string(kSchemaVersion + 1));
  expectRefused(path, "is newer than this program's");
}

TEST(SchemaTest, AnotherProgramsDatabaseIsRefusedUntouched) {
  Scratch scratch;
  const std::string path = scratch.file("other.db");
  runSql(path, "CREATE TABLE songs(title TEXT); INSERT INTO songs VALUES('x');");
  expectRefused(path, "not a pool database");
}

TEST(SchemaTest, AFileInUseByAnotherServerIsRefused) {
  Scratch scratch;
  const std::string path = scratch.file("busy.db");
  auto first = MatchStore::open(path);
  ASSERT_TRUE(first) << first.error();
  auto second = MatchStore::open(path);
  ASSERT_FALSE(second) << "two stores on one file";
  EXPECT_NE(second.error().find("locked"), std::string::npos) << second.error();
  first->reset();
  auto third = MatchStore::open(path);
  EXPECT_TRUE(third) << "still refused once the first was closed: " << third.error();
}

TEST(SchemaTest, PoolServerRefusesABadFileWithOneLineAndExitCodeOne) {
  Scratch scratch;
  const std::string path = validFile(scratch, "newer.db");
  runSql(path, "PRAGMA user_version = 99");
  const std::string before = bytesOf(path);
  server::test::ServerProcess server(121, {"--tables", "1", "--db", path});
  EXPECT_EQ(server.waitExit(std::chrono::seconds(30)), 1) << server.log();
  const std::string log = server.log();
  EXPECT_NE(log.find(path + ": schema version 99 is newer"), std::string::npos) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
  EXPECT_EQ(hashOf(bytesOf(path)), hashOf(before));
}

}  // namespace
}  // namespace pool::store::test
