// Two pool-bots play a game of three-cushion to 5 points against pool-server --fast over loopback
// DDS, on the carom table; a spectator follows every shot's frames and the score, and the
// server's stored shots, judged again, give the same points and winner.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/client_fixture.h"
#include "support/stored_match_check.h"

namespace pool::client::test {
namespace {

class ThreeCushionMatchTest : public ClientIntegrationTest {};

TEST_F(ThreeCushionMatchTest, TwoBotsPlayAGameToFivePointsOnTheCaromTable) {
  open(kThreeCushionGame, "three-cushion");
  MatchRecorder recorder(kThreeCushionGame);
  ChildProcess& server = startServer(
      {"--fast", "--game", "three-cushion", "--points", "5", "--db", scratch_->file("pool.db")});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << "the server's match never reached the recorder";
  const std::string match = recorder.firstMatch();
  const LobbyEntry* entry = recorder.client().lobby().find(match);
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(entry->table, "carom-match");
  EXPECT_EQ(entry->settings.game, rules::Game::ThreeCushion);
  EXPECT_EQ(entry->settings.points, 5);
  ChildProcess& ann = start("pool-bot",
                            {"--domain", std::to_string(domain_), "--name", "ann", "--think", "0",
                             "--seed", "3", "--timeout", "400"},
                            "ann");
  ChildProcess& ben = start("pool-bot",
                            {"--domain", std::to_string(domain_), "--name", "ben", "--think", "0",
                             "--seed", "4", "--timeout", "400"},
                            "ben");
  const auto begun = std::chrono::steady_clock::now();
  ASSERT_TRUE(recorder.pump(400s, [&] { return !ann.running() && !ben.running(); })) << logs();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  EXPECT_EQ(ann.waitExit(1s), 0) << ann.err();
  EXPECT_EQ(ben.waitExit(1s), 0) << ben.err();
  recorder.pump(5s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->phase == MatchPhase::Over;
  });
  const MatchView* last = recorder.latest(match);
  ASSERT_NE(last, nullptr);
  ASSERT_EQ(last->phase, MatchPhase::Over);
  ASSERT_TRUE(last->winner == 0 || last->winner == 1);
  const auto w = static_cast<std::size_t>(last->winner);
  // The winner reached the points set; the loser did not; every ball is on the carom table.
  EXPECT_EQ(last->end, rules::GameEnd::PointsReached);
  EXPECT_EQ(last->seats[w].points, 5);
  EXPECT_LT(last->seats[1 - w].points, 5);
  EXPECT_GE(last->seats[w].innings, 1);
  EXPECT_GE(last->seats[w].high_run, 1);
  ASSERT_EQ(last->balls.size(), 3u);
  for (const auto& b : last->balls) EXPECT_NEAR(b.pos.z(), 0.03075, 1e-9) << b.id;
  // The spectator saw every shot in motion; the store agrees.
  expectStoredMatchAgrees(recorder, server, scratch_->file("pool.db"), match, "carom-match", *last);
  std::printf("three-cushion to 5, match %s: %u shots in %.1f s, %d-%d, innings %d-%d\n",
              match.c_str(), last->shot_number, seconds, last->seats[0].points,
              last->seats[1].points, last->seats[0].innings, last->seats[1].innings);
}

}  // namespace
}  // namespace pool::client::test
