// pool-sim --db PATH --match ID --shot N: a stored shot run again gives the stored event log, and a
// bad name of a shot is one line on stderr with exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "scenario/process_runner.h"
#include "server/store/match_store.h"
#include "store_fixture.h"
#include "stored_break.h"

namespace pool::store::test {
namespace {

const std::string kSim = std::string(POOL_BIN_DIR) + "/pool-sim";

/// A database holding the break of a seated match (shot 1 of srv-1); returns its stored events.
physics::EventLog storeBreakIn(const std::string& path) {
  auto store = MatchStore::open(path);
  EXPECT_TRUE(store) << store.error();
  if (!store) return {};
  BrokenMatch b;
  storeBreak(**store, b);
  return b.answer.record ? b.answer.record->events : physics::EventLog{};
}

TEST(StoredShotCliTest, AStoredShotRunsAgainToItsStoredEvents) {
  Scratch scratch;
  const std::string db = scratch.file("pool.db");
  const physics::EventLog stored = storeBreakIn(db);
  ASSERT_GT(stored.size(), 20u);
  const auto r =
      pool::scenario::testing::runProcess({kSim, "--db", db, "--match", "srv-1", "--shot", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto result = nlohmann::json::parse(r.out);
  const auto& events = result.at("events");
  ASSERT_EQ(events.size(), stored.size());
  for (std::size_t i = 0; i < stored.size(); ++i) {
    EXPECT_EQ(events[i].at("t").get<double>(), stored[i].t) << "event " << i;
    EXPECT_EQ(events[i].at("type").get<std::string>(), physics::toString(stored[i].type))
        << "event " << i;
  }
}

TEST(StoredShotCliTest, AShotThatIsNotStoredIsOneLineAndExitCodeTwo) {
  Scratch scratch;
  const std::string db = scratch.file("pool.db");
  storeBreakIn(db);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{kSim, "--db", db, "--match", "srv-1", "--shot", "2"}, "--shot 2: match srv-1 has no such"},
      {{kSim, "--db", db, "--match", "srv-9", "--shot", "1"}, "--match srv-9: no such match"},
      {{kSim, "--db", scratch.file("none.db"), "--match", "srv-1", "--shot", "1"}, "no such file"},
      {{kSim, "--db", db, "--match", "srv-1"}, "all of --db, --match and --shot"},
  };
  for (const auto& [argv, why] : cases) {
    const auto r = pool::scenario::testing::runProcess(argv);
    EXPECT_EQ(r.exit_code, 2) << why;
    EXPECT_EQ(r.out, "") << why;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(scratch.file("none.db"))) << "pool-sim made a database";
}

}  // namespace
}  // namespace pool::store::test
