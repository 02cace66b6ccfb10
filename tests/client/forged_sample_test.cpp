// Server-signed samples as the client library takes them: forged states, frames and results
// (unsigned, or signed by another key) are dropped and change nothing; impossible jumps are
// dropped however they are signed; a server whose key changed is refused until its pin is
// forgotten.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "client/net/game_client.h"
#include "client/net/server_pins.h"
#include "support/client_fixture.h"
#include "support/client_watcher.h"
#include "support/forger.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

class ForgedSampleTest : public ClientIntegrationTest {};

TEST_F(ForgedSampleTest, ForgedStateFrameAndResultAreDroppedAndChangeNothing) {
  open(kForgedSamples, "forged");
  startServer({"--fast"});
  Watcher w(kForgedSamples);
  w.client.requestSpectate("srv-1");
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.state("srv-1") != nullptr; })) << logs();
  ASSERT_TRUE(w.logged("server 'srv': key ")) << "the server's key was pinned at first sight";
  const MatchView before = *w.client.state("srv-1");
  const auto dropped_before = w.client.unreadable();

  pool::test::Forger forger(kForgedSamples);
  // Unsigned, then signed by a key that is not the server's.
  ASSERT_TRUE(forger.publishState("srv-1", 0xfffffff0u, before.shot_number));
  forger.signWith(protocol::generateKeyPair());
  ASSERT_TRUE(forger.publishState("srv-1", 0xfffffff0u, before.shot_number));
  ASSERT_TRUE(forger.publishFrame("srv-1", 0xffffffffu));
  ASSERT_TRUE(forger.publishResult("srv-1", 1, before.shot_number + 1));

  // Each of the four arrives and is counted as dropped: nothing is handed out, nothing changes.
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.unreadable() >= dropped_before + 4; }))
      << "dropped " << w.client.unreadable() - dropped_before << " of 4; " << logs();
  EXPECT_FALSE(
      w.handedOut<MatchView>([](const MatchView& v) { return v.revision == 0xfffffff0u; }));
  EXPECT_FALSE(w.handedOut<TableFrame>([](const TableFrame& f) { return f.shot_number > 1000; }));
  EXPECT_FALSE(w.handedOut<ShotReport>([](const ShotReport& r) { return r.game_over; }));
  const MatchView* after = w.client.state("srv-1");
  ASSERT_NE(after, nullptr);
  EXPECT_EQ(after->revision, before.revision);
  EXPECT_EQ(after->phase, before.phase);
  EXPECT_TRUE(w.logged("unsigned")) << ::testing::PrintToString(w.lines);
  EXPECT_TRUE(w.logged("but the key pinned for that server is"))
      << ::testing::PrintToString(w.lines);

  // The real server's samples still go through: a player sits down, the state moves on.
  GameClient player({kForgedSamples, "", "Ada", {}, {}});
  Reask reask;
  ASSERT_TRUE(w.pumpUntil([&] {
    player.poll();
    const MatchView* v = w.client.state("srv-1");
    if (v && v->seats[0].name == "Ada") return true;
    reask([&] { player.requestSeat("srv-1", 0); });
    return false;
  })) << logs();
  EXPECT_GT(w.client.state("srv-1")->revision, before.revision);
}

TEST_F(ForgedSampleTest, ImpossibleJumpsAreDroppedEvenWhenSigned) {
  open(kImpossibleJumps, "jumps");
  // A "server" of the forger's own: its key is pinned at first sight, so its signatures verify.
  pool::test::Forger server(kImpossibleJumps);
  server.signWith(protocol::generateKeyPair());
  Watcher w(kImpossibleJumps);
  // The match has a partition of its own: the watcher follows it as a spectator would.
  w.client.observe("evil-1");
  ASSERT_TRUE(server.publishState("evil-1", 5, 2, pool_PHASE_OPEN, -1));
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.state("evil-1") != nullptr; }));
  ASSERT_EQ(w.client.state("evil-1")->revision, 5u);
  const auto dropped_before = w.client.unreadable();

  ASSERT_TRUE(server.publishState("evil-1", 0xfffffff0u, 2));  // over, far beyond revision 5
  ASSERT_TRUE(server.publishState("evil-1", 6, 0xffffffffu));  // a shot far beyond shot 2
  ASSERT_TRUE(server.publishFrame("evil-1", 0xffffffffu));
  ASSERT_TRUE(server.publishResult("evil-1", 1, 0xffffffffu));
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.unreadable() >= dropped_before + 4; }))
      << ::testing::PrintToString(w.lines);
  EXPECT_EQ(w.client.state("evil-1")->revision, 5u);
  EXPECT_EQ(w.client.state("evil-1")->phase, MatchPhase::Open);
  EXPECT_TRUE(w.logged("is an impossible jump")) << ::testing::PrintToString(w.lines);

  // The next revision is fine.
  ASSERT_TRUE(server.publishState("evil-1", 6, 3, pool_PHASE_OPEN, -1));
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.state("evil-1")->revision == 6u; }));
}

TEST_F(ForgedSampleTest, AChangedServerKeyIsRefusedUntilItsPinIsForgotten) {
  open(kChangedKey, "changed-key");
  const std::filesystem::path pins = file("config/pool/servers");
  {
    ChildProcess& first = startServer({"--fast", "--db", file("first.db")});
    Watcher w(kChangedKey, pins);
    w.client.requestSpectate("srv-1");
    ASSERT_TRUE(w.pumpUntil([&] { return w.client.state("srv-1") != nullptr; })) << logs();
    first.kill(SIGTERM);
    ASSERT_TRUE(first.waitExit(10s));
  }
  struct stat st {};
  ASSERT_EQ(::stat(pins.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u) << "the pin file is the owner's only";

  // The same server id with another database: another key.
  startServer({"--fast", "--db", file("second.db")});
  {
    Watcher w(kChangedKey, pins);
    w.client.requestSpectate("srv-1");
    ASSERT_TRUE(w.pumpUntil([&] { return w.logged("the server's key changed"); }))
        << ::testing::PrintToString(w.lines) << logs();
    EXPECT_EQ(w.client.state("srv-1"), nullptr);
    EXPECT_TRUE(w.logged("--forget-server-key srv"));
  }
  // The operator forgets the pin (as pool-client --forget-server-key does): the new key is pinned.
  ChildProcess& forget = start("pool-client", {"--forget-server-key", "srv"}, "forget");
  ASSERT_EQ(forget.waitExit(20s), 0) << forget.err();
  Watcher w(kChangedKey, pins);
  w.client.requestSpectate("srv-1");
  ASSERT_TRUE(w.pumpUntil([&] { return w.client.state("srv-1") != nullptr; }))
      << ::testing::PrintToString(w.lines) << logs();
}

}  // namespace
}  // namespace pool::client::test
