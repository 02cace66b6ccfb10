// pool-client --spectate joins a match in play: it prints the current state at once, then every
// later shot's result and frame count, up to the end of the match.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

class SpectatorTest : public ClientIntegrationTest {};

std::vector<nlohmann::json> jsonLines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    auto json = nlohmann::json::parse(line, nullptr, false);
    if (!json.is_discarded()) out.push_back(std::move(json));
  }
  return out;
}

TEST_F(SpectatorTest, ALateSpectatorGetsTheStateAtOnceThenEveryLaterShot) {
  open(kSpectator, "spectator");
  MatchRecorder recorder(kSpectator);
  startServer({"--fast"});
  // Bots that think a little give the match a pace a spectator can join in the middle of.
  ChildProcess& alice = startBot("alice", 3, {"--think", "0.25"});
  ChildProcess& bob = startBot("bob", 4, {"--think", "0.25"});
  // The spectator comes after the break: no 8-ball break ends the game (the 8 down on the break
  // is re-spotted or racked again), so the match is in play then. Any later shot may end it: a
  // bot once sank the 8 on the second shot, before the spectator came after the third.
  const std::uint32_t kJoinAfter = 1;
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return (v && v->shot_number >= kJoinAfter) || stalledOnLayout(recorder);
  })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder))
      << "the match stalled before the spectator came: the physics refuses a layout it left";
  const std::string match = recorder.firstMatch();
  const std::uint32_t shots_at_join = recorder.latest(match)->shot_number;
  ASSERT_TRUE(inPlay(recorder.latest(match)->phase)) << "the match ended before the spectator came";

  // The first state arrives on joining, with its layout. The bound is the process's start and
  // DDS discovery on two loaded cores under the sanitizers, with margin: 15 s.
  ChildProcess& spectator = startSpectator("any");
  const auto started = std::chrono::steady_clock::now();
  bool got_state = false;
  while (!got_state && std::chrono::steady_clock::now() - started < 15s) {
    for (const auto& line : jsonLines(spectator.out())) {
      if (line.value("type", "") == "match_state") {
        got_state = true;
        EXPECT_EQ(line.value("match", ""), match);
        EXPECT_GE(line.value("shot_number", 0u), shots_at_join);
        EXPECT_EQ(line.value("balls", 0u), 16u) << "the layout comes with the state";
      }
    }
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_TRUE(got_state) << spectator.out() << spectator.err();

  // It follows the match to its end and exits by itself. A match that stalls (the server refusing
  // shots because the physics refuses the layout it left) fails the test at once, with the layout.
  const bool ended =
      recorder.pump(80s, [&] { return !spectator.running() || stalledOnLayout(recorder); });
  ASSERT_TRUE(ended) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder))
      << "the match stalled after the spectator came: the physics refused a layout it left\n"
      << layoutOf(recorder, match) << logs();
  EXPECT_EQ(spectator.waitExit(1s), 0);
  alice.kill(SIGKILL);
  bob.kill(SIGKILL);

  // Every shot the recorder saw end after the first state the spectator printed has its result
  // and a frame count in the spectator's output.
  const auto lines = jsonLines(spectator.out());
  std::uint32_t first_state_shot = 0;
  std::set<std::uint32_t> results, counted;
  std::string last_phase;
  for (const auto& line : lines) {
    const std::string type = line.value("type", "");
    if (type == "match_state") {
      if (last_phase.empty()) first_state_shot = line.value("shot_number", 0u);
      last_phase = line.value("phase", "");
    } else if (type == "shot_result" && line.value("final", false)) {
      results.insert(line.value("shot_number", 0u));
    } else if (type == "snapshots") {
      counted.insert(line.value("shot_number", 0u));
      EXPECT_GT(line.value("count", 0u), 0u) << line.dump();
    }
  }
  EXPECT_EQ(last_phase, "over");
  const auto finals = recorder.finals(match);
  ASSERT_FALSE(finals.empty());
  EXPECT_GT(finals.rbegin()->first, first_state_shot) << "no shot after the spectator joined";
  for (const auto& [n, report] : finals) {
    if (n <= first_state_shot) continue;
    EXPECT_TRUE(results.count(n)) << "no result for shot " << n;
    EXPECT_TRUE(counted.count(n)) << "no frame count for shot " << n;
  }
}

}  // namespace
}  // namespace pool::client::test
