// pool-server's process life: clean exit on SIGTERM and SIGINT; flags, config file and their order.
#include <gtest/gtest.h>

#include <fstream>

#include "server/server_config.h"
#include "server_fixture.h"

namespace pool::server::test {
namespace {

class ServerLifecycle : public ServerTest {};

TEST_F(ServerLifecycle, SigtermEndsTheServerCleanlyWithoutWaiting) {
  start(kSigterm, {"--tables", "2", "--fast"});
  TestClient watcher(kSigterm, "w");
  ASSERT_TRUE(watcher.waitForServer(2));
  server_->signal(SIGTERM);
  // A server that waited on anything on its way out (a shot, a peer, a DDS lease of 10 s) would
  // miss 5 s; how much of them a clean exit takes is the machine's.
  const auto code = server_->waitExit(5s);
  ASSERT_TRUE(code) << "still running 5 s after SIGTERM";
  EXPECT_EQ(*code, 0);
  // The lobby entries were disposed on the way out.
  EXPECT_TRUE(watcher.waitUntil([&] { return watcher.disposed_infos.size() == 2; }, 3s));
}

TEST_F(ServerLifecycle, NewMatchesAreOpenedOnRequestAndSigintEndsTheServer) {
  start(kNewMatch, {"--max-matches", "2"});
  TestClient a(kNewMatch, "a");
  ASSERT_TRUE(a.waitForServer(0));
  const auto created = a.join(pool_JOIN_SEAT, "new", "Ada");
  ASSERT_TRUE(created);
  EXPECT_EQ(created->outcome, pool_JOIN_ACCEPTED);
  EXPECT_STREQ(created->match, "t-1");
  EXPECT_TRUE(a.waitUntil([&] { return a.liveInfos() == 1; }));
  // --max-matches: a client cannot make the server open tables without limit.
  TestClient b(kNewMatch, "b"), c(kNewMatch, "c");
  ASSERT_TRUE(b.waitForServer(1));
  ASSERT_TRUE(c.waitForServer(1));
  const auto second = b.join(pool_JOIN_SEAT, "new", "Bob");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->outcome, pool_JOIN_ACCEPTED);
  const auto third = c.join(pool_JOIN_SEAT, "new", "Cy");
  ASSERT_TRUE(third);
  EXPECT_EQ(third->outcome, pool_JOIN_SERVER_FULL) << net::textOf(third->reason);
  server_->signal(SIGINT);
  const auto code = server_->waitExit(5s);
  ASSERT_TRUE(code);
  EXPECT_EQ(*code, 0);
}

TEST(ServerConfig, FileValuesApplyAndFlagsWin) {
  const std::string path = "/tmp/pool-server-config-test-" + std::to_string(::getpid()) + ".json";
  std::ofstream(path) << R"({"domain": 7, "tables": 3, "snapshot_hz": 30, "fast": true,
                             "server-id": "lab", "grace": 5})";
  const char* argv[] = {"pool-server", "--config", path.c_str(), "--tables", "9"};
  const ConfigOutcome out = parseConfig(5, argv);
  std::remove(path.c_str());
  ASSERT_FALSE(out.exit_code);
  EXPECT_EQ(out.config.domain, 7u);
  EXPECT_EQ(out.config.tables, 9);
  EXPECT_EQ(out.config.snapshot_hz, 30.0);
  EXPECT_TRUE(out.config.fast);
  EXPECT_EQ(out.config.server_id, "lab");
  EXPECT_EQ(out.config.grace, 5.0);
}

TEST(ServerConfig, BadValuesAreRefusedWithTheirKey) {
  ServerConfig c;
  EXPECT_EQ(applyConfigJson(R"({"grace": "soon"})", c).error(), "grace: wrong type");
  EXPECT_EQ(applyConfigJson("[1]", c).error(), "not a JSON object");
  c.snapshot_hz = 0;
  EXPECT_NE(checkConfig(c).error().find("snapshot-hz"), std::string::npos);
  const char* argv[] = {"pool-server", "--domain", "500"};
  EXPECT_EQ(parseConfig(3, argv).exit_code, 2);
  ServerConfig capped;
  capped.max_matches = 0;
  EXPECT_NE(checkConfig(capped).error().find("max-matches"), std::string::npos);
  capped.max_matches = 3;
  capped.tables = 4;
  EXPECT_NE(checkConfig(capped).error().find("at most max-matches"), std::string::npos);
  const char* more_tables_than_matches[] = {"pool-server", "--tables", "5", "--max-matches", "2"};
  EXPECT_EQ(parseConfig(5, more_tables_than_matches).exit_code, 2);
}

TEST(ServerConfig, AnUnknownLogLevelOrAServerIdThatCutsMatchIdsIsRefused) {
  ServerConfig c;
  c.log_level = "bogus";  // spdlog would quietly read it as "off"
  EXPECT_NE(checkConfig(c).error().find("log-level"), std::string::npos);
  c.log_level = "off";
  EXPECT_TRUE(checkConfig(c).ok());
  // A 39-byte id leaves no room for "-<n>" in a 39-byte match id.
  c.server_id = std::string(39, 'a');
  EXPECT_NE(checkConfig(c).error().find("server-id"), std::string::npos);
  c.server_id = std::string(kMaxServerIdLength, 'a');
  EXPECT_TRUE(checkConfig(c).ok());
  EXPECT_LE(c.server_id.size() + 1 + 14, 39u);  // "-" and n up to 14 digits
  c.server_id = "lab\n2";
  EXPECT_NE(checkConfig(c).error().find("server-id"), std::string::npos);
  const char* argv[] = {"pool-server", "--log-level", "verbose"};
  EXPECT_EQ(parseConfig(3, argv).exit_code, 2);
}

}  // namespace
}  // namespace pool::server::test
