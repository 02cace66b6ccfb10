// pool-server --replay MATCH --db PATH: a finished bot match played again for spectators shot by
// shot, with the stored verdicts, events and winner, and the database left as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "server/store/match_store.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class ServerReplayTest : public ClientIntegrationTest {};

TEST_F(ServerReplayTest, AStoredMatchIsPlayedAgainShotByShotForSpectators) {
  open(kReplay, "replay");
  const std::string db = file("pool.db");

  // A bot match played to its end on a server keeping it in `db`.
  ChildProcess& server = startServer({"--fast", "--db", db});
  ChildProcess& alice = startBot("alice", 3);
  ChildProcess& bob = startBot("bob", 4);
  MatchRecorder recorder(kReplay);
  ASSERT_TRUE(recorder.pump(90s, [&] { return !alice.running() && !bob.running(); })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder))
      << "the match stalled: the server refused shots because the physics refused the layout it "
         "had left\n"
      << layoutOf(recorder, recorder.firstMatch()) << logs();
  server.kill(SIGTERM);
  ASSERT_EQ(server.waitExit(10s), 0) << server.err();
  auto store = store::MatchStore::open(db);
  ASSERT_TRUE(store) << store.error();
  const auto stored = (*store)->match("srv-1");
  ASSERT_TRUE(stored);
  ASSERT_EQ(stored->game.phase, rules::Phase::Over);
  const auto shots = (*store)->shots("srv-1");
  store->reset();  // closed: the file alone holds the match
  const std::string before = bytesOf(db);

  // Played again as match rep-1 of a replaying server, watched by the recorder.
  ChildProcess& replay = start("pool-server",
                               {"--domain", std::to_string(kReplay), "--server-id", "rep", "--fast",
                                "--replay", "srv-1", "--db", db},
                               "replay");
  ASSERT_TRUE(recorder.pump(60s, [&] {
    const MatchView* v = recorder.latest("rep-1");
    return v && v->phase == MatchPhase::Over;
  })) << replay.err();
  ASSERT_TRUE(recorder.pump(10s, [&] {
    return replay.err().find("replay rep-1 done") != std::string::npos;
  })) << replay.err();
  EXPECT_NE(replay.err().find("replay rep-1 done: " + std::to_string(shots.size()) +
                              " commands replayed, 0 differ"),
            std::string::npos)
      << replay.err();
  const auto finals = recorder.finals("rep-1");
  std::size_t strokes = 0;
  for (const auto& s : shots) {
    if (!s.record.shoots) continue;
    ++strokes;
    const auto it = finals.find(s.record.shot_number);
    ASSERT_NE(it, finals.end()) << "shot " << s.record.shot_number << " not replayed";
    EXPECT_EQ(it->second.verdict_text, s.verdict_text) << "shot " << s.record.shot_number;
    ASSERT_EQ(it->second.events.size(), s.record.events.size()) << "shot " << s.record.shot_number;
    for (std::size_t i = 0; i < s.record.events.size(); ++i) {
      EXPECT_EQ(it->second.events[i].type, s.record.events[i].type);
      EXPECT_EQ(it->second.events[i].ball_a, s.record.events[i].ball_a);
    }
  }
  EXPECT_GT(strokes, 0u);
  const MatchView* v = recorder.latest("rep-1");
  EXPECT_EQ(v->winner, stored->game.winner);
  EXPECT_EQ(v->shot_number, stored->shot_number);
  EXPECT_EQ(bytesOf(db), before) << "the replay wrote to the database";
  std::printf("replayed %zu shots of srv-1 as rep-1, winner seat %d\n", strokes, v->winner);
}

}  // namespace
}  // namespace pool::client::test
