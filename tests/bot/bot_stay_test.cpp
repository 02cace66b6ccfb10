// pool-bot --stay (the main job's bot against a player): at game over it asks for a rematch and
// plays it while its opponent keeps the seat, and leaves once the opponent has left.
#include <gtest/gtest.h>

#include <csignal>

#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

/// This file's DDS domain (80–89 are the concession and replay tests').
constexpr Domain kStayingBot = static_cast<Domain>(81);

class BotStayTest : public ClientIntegrationTest {};

TEST_F(BotStayTest, AStayingBotPlaysRematchesUntilItsOpponentLeaves) {
  open(kStayingBot, "stay");
  MatchRecorder recorder(kStayingBot);
  startServer({"--fast", "--grace", "2"});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << "the server's match never reached the recorder";
  const std::string match = recorder.firstMatch();
  ChildProcess& alice = startBot("alice", 41, {"--stay"});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].name == "alice";
  })) << logs();
  // Bob stays too, and concedes each rack on his first turn: each game ends at once.
  ChildProcess& bob = startBot("bob", 42, {"--stay", "--concede-from-rack", "1"});

  // Two games over, one after the other at the same table: the rematch was asked and played. A
  // game is a race to one rack (pool-server's default), so the second one ends at rack 2 or later;
  // games are told apart by their rack, not by phase changes in the samples as they arrived
  // (under the sanitizers those once counted two games over while the latest state was rack 1).
  const auto secondGameOver = [&] {
    for (const auto& st : recorder.states(match)) {
      if (st.phase == MatchPhase::Over && st.rack >= 2) return true;
    }
    return false;
  };
  ASSERT_TRUE(recorder.pump(60s, secondGameOver)) << "no second game ended at the table\n"
                                                  << logs();
  EXPECT_TRUE(alice.running()) << "alice left at game over: " << alice.err();
  EXPECT_TRUE(bob.running()) << "bob left at game over: " << bob.err();

  // Bob goes; once the server frees his seat (2 s of grace at a finished game), alice leaves.
  bob.kill(SIGTERM);
  ASSERT_TRUE(recorder.pump(30s, [&] { return !alice.running(); })) << logs();
  EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
  EXPECT_NE(alice.lastLine().find("result: win"), std::string::npos) << alice.lastLine();
}

}  // namespace
}  // namespace pool::client::test
