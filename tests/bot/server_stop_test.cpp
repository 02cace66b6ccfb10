// A server stopped for 20 s (SIGSTOP, as a closed laptop lid or a stalled VM does) and then
// continued forfeits nobody: the present players are back at once and the match ends normally.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <thread>

#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

class ServerStopTest : public ClientIntegrationTest {};

TEST_F(ServerStopTest, AServerStoppedTwentySecondsForfeitsNobody) {
  open(kServerStopped, "server-stop");
  MatchRecorder recorder(kServerStopped);
  ChildProcess& server = startServer({"--fast", "--grace", "30"});
  ChildProcess& alice = startBot("alice", 21, {"--think", "0.3"});
  ChildProcess& bob = startBot("bob", 22, {"--think", "0.3"});

  // How long each seat is shown away, on this process's clock (it keeps running throughout).
  using Clock = std::chrono::steady_clock;
  std::map<int, Clock::time_point> away_since;
  double longest_away = 0.0;
  int aways = 0;
  const auto watch = [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    if (!v || v->seats[0].name.empty() || v->seats[1].name.empty()) return;
    for (int s = 0; s < 2; ++s) {
      const bool away = !v->seats[static_cast<std::size_t>(s)].connected;
      const auto it = away_since.find(s);
      if (away && it == away_since.end()) {
        away_since[s] = Clock::now();
        ++aways;
      } else if (!away && it != away_since.end()) {
        longest_away = std::max(longest_away,
                                std::chrono::duration<double>(Clock::now() - it->second).count());
        away_since.erase(it);
      }
    }
  };

  // Mid-match: a few shots played, both seated and present.
  ASSERT_TRUE(recorder.pump(40s,
                            [&] {
                              watch();
                              const MatchView* v = recorder.latest(recorder.firstMatch());
                              return v && inPlay(v->phase) && v->shot_number >= 2;
                            }))
      << "no match under way\n"
      << logs();
  const std::uint32_t shots_before = recorder.latest(recorder.firstMatch())->shot_number;

  server.kill(SIGSTOP);
  // The recorder keeps reading (nothing comes) while the server is stopped.
  recorder.pump(20s, [&] {
    watch();
    return false;
  });
  server.kill(SIGCONT);

  // The match plays on, and ends normally for both players.
  ASSERT_TRUE(recorder.pump(30s,
                            [&] {
                              watch();
                              const MatchView* v = recorder.latest(recorder.firstMatch());
                              return stalledOnLayout(recorder) ||
                                     (v && v->shot_number > shots_before);
                            }))
      << "no shot after the server continued\n"
      << logs();
  recorder.pump(90s, [&] {
    watch();
    return stalledOnLayout(recorder) || (!alice.running() && !bob.running());
  });
  ASSERT_FALSE(stalledOnLayout(recorder)) << layoutOf(recorder, recorder.firstMatch());
  // The bots may exit on the last state before the recorder has taken it: a moment more for it.
  recorder.pump(10s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return v && v->phase == MatchPhase::Over;
  });
  for (const auto& [seat, since] : away_since) {
    longest_away =
        std::max(longest_away, std::chrono::duration<double>(Clock::now() - since).count());
  }
  std::printf("server stopped 20 s: seats shown away %d times, the longest for %.2f s\n", aways,
              longest_away);
  EXPECT_LT(longest_away, 10.0) << "a present player was shown away for long\n" << logs();
  EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
  EXPECT_EQ(alice.lastLine().rfind("result: ", 0), 0u) << alice.out();
  const MatchView* last = recorder.latest(recorder.firstMatch());
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(last->phase, MatchPhase::Over) << [&] {
    std::string text = "match " + last->match + " r" + std::to_string(last->revision) +
                       ", followed " + std::to_string(recorder.client().followed().size()) +
                       ", states:";
    for (const auto& st : recorder.states(last->match)) {
      text += " r" + std::to_string(st.revision) + "/p" + std::to_string(int(st.phase));
    }
    return text + "\n" + logs();
  }();
  EXPECT_NE(last->end, rules::GameEnd::Forfeit) << "forfeited by a server that was not running";
  EXPECT_NE(server.err().find("the server was not running for"), std::string::npos) << server.err();
}

}  // namespace
}  // namespace pool::client::test
