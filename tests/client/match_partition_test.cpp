// Each match in a partition of its own: a spectator of one match receives nothing of another
// being played beside it, and one that switches matches follows the new one (its latest state
// at once, then its shots) and drops the old.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "support/client_fixture.h"
#include "support/client_watcher.h"

namespace pool::client::test {
namespace {

class MatchPartitionTest : public ClientIntegrationTest {};

/// Whether `w` was handed any state, result or frame of `match`.
bool heardOf(const Watcher& w, const std::string& match) {
  return w.handedOut<MatchView>([&](const MatchView& v) { return v.match == match; }) ||
         w.handedOut<ShotReport>([&](const ShotReport& r) { return r.match == match; }) ||
         w.handedOut<TableFrame>([&](const TableFrame& f) { return f.match == match; });
}

TEST_F(MatchPartitionTest, ASpectatorHearsOnlyItsMatchAndFollowsTheOneItSwitchesTo) {
  open(kPartitionSwitch, "partitions");
  MatchRecorder recorder(kPartitionSwitch);
  start("pool-server",
        {"--domain", std::to_string(kPartitionSwitch), "--tables", "2", "--server-id", "srv",
         "--fast"},
        "server");
  // The bots sit at the first free table, srv-1; srv-2 stays free.
  ChildProcess& alice = startBot("alice", 31, {"--think", "0.3"});
  ChildProcess& bob = startBot("bob", 32, {"--think", "0.3"});
  Watcher w(kPartitionSwitch);
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.lobby().find("srv-2") != nullptr; })) << logs();
  w.client.requestSpectate("srv-2");

  // Both watch while srv-1 is played: the recorder (every match) sees its shots, w none of it.
  ASSERT_TRUE(recorder.pump(60s, [&] {
    w.pumpUntil([] { return true; });
    const MatchView* v = recorder.latest("srv-1");
    return v && v->shot_number >= 3 && !recorder.frames("srv-1", 2).empty();
  })) << logs();
  EXPECT_TRUE(w.pumpUntil([&] { return w.client.state("srv-2") != nullptr; }));
  EXPECT_FALSE(heardOf(w, "srv-1")) << "a spectator of srv-2 received samples of srv-1";
  EXPECT_EQ(w.client.followed(), std::set<std::string>{"srv-2"});
  EXPECT_EQ(w.client.state("srv-1"), nullptr);

  // It switches to srv-1: the latest state at once (kept for late readers), then later shots.
  w.client.requestLeave("srv-2");
  w.client.requestSpectate("srv-1");
  const std::uint32_t shots = recorder.latest("srv-1")->shot_number;
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.state("srv-1") != nullptr; }, 10s))
      << "no state of srv-1 for a late spectator";
  EXPECT_GE(w.client.state("srv-1")->shot_number, shots);
  const bool over = w.client.state("srv-1")->phase == MatchPhase::Over;
  if (!over) {
    EXPECT_TRUE(w.pumpUntil(
        [&] {
          return w.handedOut<TableFrame>(
              [&](const TableFrame& f) { return f.match == "srv-1" && f.shot_number > shots; });
        },
        60s))
        << "no frame of srv-1's later shots\n"
        << logs();
  }
  EXPECT_TRUE(
      w.pumpUntil([&] { return w.client.followed() == std::set<std::string>{"srv-1"}; }, 10s))
      << "srv-2 is still followed";
  alice.kill(SIGTERM);
  bob.kill(SIGTERM);
}

}  // namespace
}  // namespace pool::client::test
