// Two pool-bots play a whole match against pool-server --fast over loopback DDS; the recorded
// shots, replayed through the rules engine, give the same winner.
#include <gtest/gtest.h>

#include "support/client_fixture.h"
#include "support/match_replay.h"

namespace pool::client::test {
namespace {

class BotMatchTest : public ClientIntegrationTest {};

TEST_F(BotMatchTest, TwoBotsPlayAFullMatchToAWinner) {
  open(kFullMatch, "full");
  MatchRecorder recorder(kFullMatch);
  startServer({"--fast"});
  // The recorder must hold the match's state before any bot sits down: states are keep-last 1,
  // and with --fast the break can follow the second seat within milliseconds.
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << "the server's match never reached the recorder";
  ChildProcess& alice = startBot("alice", 11);
  ChildProcess& bob = startBot("bob", 22);
  ASSERT_TRUE(recorder.waitForPlayers(2, 20s)) << "the bots' command writers never appeared";

  // Both bots end on their own, well within the bound; the recorder watches meanwhile.
  const auto start = std::chrono::steady_clock::now();
  const bool ended = recorder.pump(
      100s, [&] { return stalledOnLayout(recorder) || (!alice.running() && !bob.running()); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(stalledOnLayout(recorder))
      << "the server refuses every shot: the physics left a ball where its own setBalls refuses "
         "it (common/physics checkPlacement vs. balls at rest in a pocket mouth)\n"
      << recorder.rejections().back().reject_text << "\n"
      << layoutOf(recorder, recorder.firstMatch());
  ASSERT_TRUE(ended) << logs();
  // How long the match took is the bots' play and the machine's (the pump's 100 s bounds it).
  std::printf("the bots' match took %.1f s\n", seconds);
  EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();

  // One winner and one loser, and the server agrees on who.
  const std::string a = alice.lastLine(), b = bob.lastLine();
  EXPECT_TRUE((a.rfind("result: win", 0) == 0 && b.rfind("result: loss", 0) == 0) ||
              (a.rfind("result: loss", 0) == 0 && b.rfind("result: win", 0) == 0))
      << a << " / " << b;
  recorder.pump(2s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return v && v->phase == MatchPhase::Over;
  });
  const std::string match = recorder.firstMatch();
  const MatchView* final_state = recorder.latest(match);
  ASSERT_NE(final_state, nullptr);
  ASSERT_EQ(final_state->phase, MatchPhase::Over);
  const std::string winner_name = a.rfind("result: win", 0) == 0 ? "alice" : "bob";
  EXPECT_EQ(final_state->winner, seatOf(*final_state, winner_name));

  // The rules engine, fed the recorded shots, reaches every verdict and the same winner.
  auto table = bot::loadTableView("wpa-9ft");
  ASSERT_TRUE(table) << table.error();
  const Replay replay = replayMatch(recorder, match, *table);
  ASSERT_TRUE(replay.error.empty()) << replay.error;
  EXPECT_EQ(replay.shots, static_cast<int>(final_state->shot_number));
  EXPECT_EQ(replay.winner, final_state->winner);
  std::printf("match %s: %d shots in %.2f s, %s\n", match.c_str(), replay.shots, seconds,
              a.c_str());
}

}  // namespace
}  // namespace pool::client::test
