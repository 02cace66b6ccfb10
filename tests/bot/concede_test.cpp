// A bot told to concede gives up each rack on its first turn in it, through a signed seat request
// to the real pool-server: the opponent wins the rack, the race goes on to the next rack and ends
// when the last one is conceded; watchers read who conceded, and the store keeps the score.
#include <gtest/gtest.h>

#include <csignal>

#include "protocol/seat_request.h"
#include "server/store/match_store.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

/// This file's DDS domain (80–89 are the concession and replay tests').
constexpr Domain kConcedeBots = static_cast<Domain>(80);

class ConcedeTest : public ClientIntegrationTest {};

TEST_F(ConcedeTest, ABotThatConcedesGivesEachRackToItsOpponentUntilTheRaceIsWon) {
  open(kConcedeBots, "concede");
  MatchRecorder recorder(kConcedeBots);
  ChildProcess& server = startServer({"--fast", "--race", "2", "--db", file("pool.db")});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << "the server's match never reached the recorder";
  const std::string match = recorder.firstMatch();

  // Alice sits first (seat 0, she breaks rack 1); Bob concedes every rack on his first turn.
  ChildProcess& alice = startBot("alice", 31);
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].name == "alice";
  })) << logs();
  ChildProcess& bob = startBot("bob", 32, {"--concede-from-rack", "1"});

  // Rack 1 conceded: Alice leads 1-0 and rack 2 is in play, with the concession in words.
  const std::string first = std::string("seat 1") + protocol::kConcededTheRack + "; rack 2";
  MatchView told;  // the state that told it (a copy: the recorder's list grows)
  ASSERT_TRUE(recorder.pump(60s, [&] {
    for (const auto& st : recorder.states(match)) {
      if (st.rack == 2 && st.last_verdict.rfind(first, 0) == 0) {
        told = st;
        return true;
      }
    }
    return false;
  })) << logs();
  EXPECT_EQ(told.seats[0].racks_won, 1);
  EXPECT_EQ(told.seats[1].racks_won, 0);
  EXPECT_TRUE(client::inPlay(told.phase)) << "the race goes on";

  // Rack 2 conceded too: the race to 2 is Alice's, 2-0, a forfeit; both bots end.
  ASSERT_TRUE(recorder.pump(60s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->phase == MatchPhase::Over;
  })) << logs();
  const MatchView over = *recorder.latest(match);
  EXPECT_EQ(over.winner, 0);
  EXPECT_EQ(over.end, rules::GameEnd::Forfeit);
  EXPECT_EQ(over.seats[0].racks_won, 2);
  EXPECT_EQ(over.seats[1].racks_won, 0);
  EXPECT_EQ(over.last_verdict,
            std::string("seat 1") + protocol::kConcededTheRack + ": seat 0 won the match");
  ASSERT_TRUE(recorder.pump(30s, [&] { return !alice.running() && !bob.running(); })) << logs();
  EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
  EXPECT_NE(alice.lastLine().find("result: win 2-0"), std::string::npos) << alice.lastLine();
  EXPECT_NE(bob.lastLine().find("result: loss 0-2"), std::string::npos) << bob.lastLine();

  // What a restarted server would resume: the score and the concession are in the store.
  server.kill(SIGTERM);
  EXPECT_EQ(server.waitExit(20s), 0) << server.err();
  auto store = store::MatchStore::open(file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  const auto stored = (*store)->match(match);
  ASSERT_TRUE(stored) << match;
  EXPECT_EQ(stored->seats[0].racks_won, 2);
  EXPECT_EQ(stored->seats[1].racks_won, 0);
  EXPECT_EQ(stored->game.winner, 0);
  EXPECT_EQ(stored->last_verdict, over.last_verdict);
}

}  // namespace
}  // namespace pool::client::test
