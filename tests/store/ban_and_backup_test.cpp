// Banned keys kept in the file, and online backups: a copy that opens, and refusals that write
// nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "server/store/ban_list.h"
#include "server/store/match_store.h"
#include "server/store/online_backup.h"
#include "store_fixture.h"

namespace pool::store::test {
namespace {

const std::vector<std::uint8_t> kKey(32, 7);

TEST(BanList, BansAreKeptInTheFileInTheOrderMade) {
  Scratch scratch;
  const std::string path = scratch.file("pool.db");
  {
    auto store = MatchStore::open(path);
    ASSERT_TRUE(store) << store.error();
    EXPECT_TRUE(addBan((*store)->database(), kKey, "first"));
    EXPECT_FALSE(addBan((*store)->database(), kKey, "second"));  // the first reason stays
    EXPECT_TRUE(addBan((*store)->database(), std::vector<std::uint8_t>(32, 9), "other"));
  }
  auto store = MatchStore::open(path);
  ASSERT_TRUE(store);
  auto kept = bans((*store)->database());
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].public_key, kKey);
  EXPECT_EQ(kept[0].reason, "first");
  EXPECT_EQ(kept[0].banned_at.size(), 19u);  // "YYYY-MM-DD HH:MM:SS"
  EXPECT_TRUE(removeBan((*store)->database(), kKey));
  EXPECT_FALSE(removeBan((*store)->database(), kKey));
  EXPECT_EQ(bans((*store)->database()).size(), 1u);
}

TEST(OnlineBackup, TheCopyOpensAsAPoolDatabaseWhileTheSourceStaysOpen) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store);
  (*store)->saveMatches("srv", 3, {});
  addBan((*store)->database(), kKey, "kept in the copy");
  const auto copy = backupTo((*store)->database(), scratch.file("copy.db"));
  ASSERT_TRUE(copy) << copy.error();
  EXPECT_GT(copy->pages, 0);
  EXPECT_EQ(copy->bytes, static_cast<std::int64_t>(std::filesystem::file_size(copy->path)));
  EXPECT_FALSE(std::filesystem::exists(scratch.file("copy.db.partial")));
  // The source is still the server's to write.
  (*store)->saveMatches("srv", 4, {});
  auto opened = MatchStore::open(scratch.file("copy.db"));
  ASSERT_TRUE(opened) << opened.error();
  EXPECT_EQ((*opened)->serverId(), "srv");
  EXPECT_EQ((*opened)->opened(), 3u);
  ASSERT_EQ(bans((*opened)->database()).size(), 1u);
}

TEST(OnlineBackup, ABadTargetIsRefusedAndNothingIsWritten) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store);
  const std::string taken = scratch.file("taken.db");
  writeBytes(taken, "precious");
  const auto refused = [&](const std::string& path) {
    auto r = backupTo((*store)->database(), path);
    EXPECT_FALSE(r) << path;
    return r ? std::string() : r.error();
  };
  EXPECT_EQ(refused(taken), taken + ": a file is there already (not overwritten)");
  EXPECT_EQ(bytesOf(taken), "precious");
  EXPECT_EQ(refused("relative.db"), "relative.db: must be an absolute path");
  EXPECT_EQ(refused(scratch.file("no/such/folder.db")), scratch.file("no/such/folder.db") +
                                                            ": folder " + scratch.file("no/such") +
                                                            " does not exist");
  EXPECT_EQ(refused(scratch.file("")), scratch.file("") + ": names a folder, not a file");
  // The database itself is never overwritten.
  EXPECT_NE(refused(scratch.file("pool.db")).find("a file is there already"), std::string::npos);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(scratch.file("")),
                          std::filesystem::directory_iterator()),
            3);  // pool.db, its WAL, taken.db: nothing else was made
}

}  // namespace
}  // namespace pool::store::test
