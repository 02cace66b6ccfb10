// A bot killed mid-match (SIGKILL) and started again with the same name, token file and key takes
// its seat back within the grace period and plays on; one left dead past the grace period loses
// the match by forfeit; one starved past its liveliness lease notices it is away and rejoins.
#include <gtest/gtest.h>

#include <filesystem>

#include "client/net/seat_file.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

class BotRejoinTest : public ClientIntegrationTest {
 protected:
  /// Pumps until it is `name`'s turn after at least `shots` shots; false on a stall or timeout.
  bool untilTurnOf(MatchRecorder& recorder, const std::string& name, std::uint32_t shots) {
    const bool ok = recorder.pump(30s, [&] {
      const MatchView* v = recorder.latest(recorder.firstMatch());
      return stalledOnLayout(recorder) ||
             (v && inPlay(v->phase) && v->shot_number >= shots && v->shooter == seatOf(*v, name));
    });
    return ok && !stalledOnLayout(recorder);
  }

  /// Pumps until the seat of `name` shows `connected`.
  bool untilConnected(MatchRecorder& recorder, const std::string& name, bool connected,
                      std::chrono::milliseconds timeout) {
    return recorder.pump(timeout, [&] {
      const MatchView* v = recorder.latest(recorder.firstMatch());
      const int seat = v ? seatOf(*v, name) : -1;
      return seat >= 0 && v->seats[static_cast<std::size_t>(seat)].connected == connected;
    });
  }

  /// Fails, with the layout and the logs, when the match stalled on a layout the physics refused.
  ::testing::AssertionResult notStalled(const MatchRecorder& recorder) const {
    if (!stalledOnLayout(recorder)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "the match stalled: the server refused shots because the physics refused the layout "
              "it had left\n"
           << layoutOf(recorder, recorder.firstMatch()) << logs();
  }
};

TEST_F(BotRejoinTest, AKilledBotRejoinsWithItsTokenWithinTheGracePeriod) {
  open(kRejoin, "rejoin");
  MatchRecorder recorder(kRejoin);
  // A race to two racks: racks differ per match, and a first rack that ends before alice's turn
  // comes (her opponent runs it out, or pots the 8 early) leaves none to interrupt; the second
  // rack gives her one.
  // Bots of skill 0.9 (about seven pots in ten) finish the match the test watches to its end in
  // some 20 s; at the suite's usual 0.8 a race to two took up to a minute beside the sanitized
  // suite, past the wait for its end.
  startServer({"--fast", "--grace", "30", "--race", "2"});
  const std::vector<std::string> alice_args{"--skill", "0.9",          "--think",
                                            "0.2",     "--token-file", file("alice.json")};
  ChildProcess* alice = &startBot("alice", 5, alice_args);
  ChildProcess& bob = startBot("bob", 6, {"--skill", "0.9", "--think", "0.2"});
  ASSERT_TRUE(untilTurnOf(recorder, "alice", 1))
      << (stalledOnLayout(recorder) ? "stalled: the physics refuses a layout it left"
                                    : "no turn of alice to interrupt\n" + logs());

  // Killed while it is alice's turn: the seat file holds the token, the server marks her away.
  auto saved = client::readSeatFile(file("alice.json"));
  ASSERT_TRUE(saved && *saved) << "no seat file";
  alice->kill(SIGKILL);
  ASSERT_TRUE(untilConnected(recorder, "alice", false, 20s)) << "the server never noticed";
  const std::uint32_t shots_when_killed = recorder.latest(recorder.firstMatch())->shot_number;

  // Someone with a copy of the token file but not the key (which stays beside it) is refused.
  std::filesystem::copy_file(file("alice.json"), file("mallory.json"));
  ChildProcess& mallory = startBot("mallory", 11, {"--token-file", file("mallory.json")});
  EXPECT_TRUE(recorder.pump(20s, [&] {
    return mallory.err().find("refused: bad_token no seat here is bound to that key") !=
           std::string::npos;
  })) << mallory.err();
  mallory.kill(SIGKILL);
  const MatchView* held = recorder.latest(recorder.firstMatch());
  ASSERT_NE(held, nullptr);
  EXPECT_EQ(seatOf(*held, "mallory"), -1);
  EXPECT_FALSE(held->seats[static_cast<std::size_t>((*saved)->seat)].connected);

  // Started again with the same identity: it rejoins the same seat and shoots again.
  alice = &startBot("alice", 5, alice_args);
  ASSERT_TRUE(untilConnected(recorder, "alice", true, 10s)) << alice->err();
  const std::string rejoined =
      "rejoin " + (*saved)->match + " seat " + std::to_string((*saved)->seat);
  EXPECT_TRUE(recorder.pump(5s, [&] { return alice->err().find(rejoined) != std::string::npos; }))
      << alice->err();
  const auto shot_after_rejoin = [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return stalledOnLayout(recorder) || (v && v->shot_number > shots_when_killed);
  };
  ASSERT_TRUE(recorder.pump(20s, shot_after_rejoin)) << "no shot after the rejoin\n" << logs();
  ASSERT_TRUE(notStalled(recorder));
  const MatchView* v = recorder.latest(recorder.firstMatch());
  EXPECT_EQ(seatOf(*v, "alice"), (*saved)->seat);

  // The match then ends normally for both.
  recorder.pump(60s,
                [&] { return stalledOnLayout(recorder) || (!alice->running() && !bob.running()); });
  ASSERT_TRUE(notStalled(recorder));
  EXPECT_EQ(alice->waitExit(1s), 0) << alice->err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
  EXPECT_EQ(alice->lastLine().rfind("result: ", 0), 0u) << alice->out();
  EXPECT_FALSE(std::filesystem::exists(file("alice.json"))) << "the seat file outlived the match";
}

TEST_F(BotRejoinTest, ABotStalledPastItsLeaseTakesItsSeatBackAndPlaysOn) {
  open(kStarved, "starved");
  MatchRecorder recorder(kStarved);
  // A race to two racks: racks differ per match, and a first rack that ends before alice's turn
  // comes (her opponent runs it out, or pots the 8 early) leaves none to interrupt; the second
  // rack gives her one.
  // Bots of skill 0.9, as above: the match must end within the wait below (at 0.8 it once ran
  // past the bots' own 90 s beside the sanitized suite).
  startServer({"--fast", "--grace", "30", "--race", "2"});
  ChildProcess* alice = &startBot("alice", 9, {"--skill", "0.9", "--think", "0.2"});
  ChildProcess& bob = startBot("bob", 10, {"--skill", "0.9", "--think", "0.2"});
  ASSERT_TRUE(untilTurnOf(recorder, "alice", 1))
      << (stalledOnLayout(recorder) ? "stalled: the physics refuses a layout it left"
                                    : "no turn of alice to interrupt\n" + logs());

  // Stopped (like a process starved of CPU) until the server gives up on its lease, then resumed:
  // the same process, the same seat, but the server has it away and counts down the grace.
  alice->kill(SIGSTOP);
  const bool noticed = untilConnected(recorder, "alice", false, 20s);
  alice->kill(SIGCONT);
  ASSERT_TRUE(noticed) << "the server never noticed";
  const std::uint32_t shots_when_stopped = recorder.latest(recorder.firstMatch())->shot_number;
  ASSERT_TRUE(untilConnected(recorder, "alice", true, 20s)) << alice->err();
  EXPECT_NE(alice->err().find("the server shows us away"), std::string::npos) << alice->err();

  // It plays on: its next shots are accepted (no bad_token), and the match ends for both.
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return stalledOnLayout(recorder) || (v && v->shot_number > shots_when_stopped + 1);
  })) << alice->err();
  ASSERT_TRUE(notStalled(recorder));
  recorder.pump(90s,
                [&] { return stalledOnLayout(recorder) || (!alice->running() && !bob.running()); });
  ASSERT_TRUE(notStalled(recorder));
  EXPECT_EQ(alice->err().find("bad_token"), std::string::npos) << alice->err();
  EXPECT_EQ(alice->waitExit(1s), 0) << alice->err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
  EXPECT_EQ(alice->lastLine().rfind("result: ", 0), 0u) << alice->out();
  EXPECT_EQ(recorder.latest(recorder.firstMatch())->end == rules::GameEnd::Forfeit, false)
      << "forfeited although it came back";
}

TEST_F(BotRejoinTest, PastTheGracePeriodTheMatchIsForfeitedToTheOpponent) {
  open(kForfeit, "forfeit");
  MatchRecorder recorder(kForfeit);
  startServer({"--fast", "--grace", "2"});
  ChildProcess& alice = startBot("alice", 7, {"--think", "0.2"});
  // Alice sits first, so she breaks: a turn of hers comes before the match can end.
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return v && seatOf(*v, "alice") == 0;
  })) << logs();
  ChildProcess& bob = startBot("bob", 8, {"--think", "0.2"});
  ASSERT_TRUE(untilTurnOf(recorder, "alice", 0))
      << (stalledOnLayout(recorder) ? "stalled: the physics refuses a layout it left"
                                    : "no turn of alice to interrupt\n" + logs());
  alice.kill(SIGKILL);

  // Lease (net::qos::kPlayerLease, 5 s) plus grace (2 s) later the match is over, won by bob,
  // and bob says so.
  const auto killed = std::chrono::steady_clock::now();
  ASSERT_TRUE(recorder.pump(30s, [&] { return !bob.running(); })) << bob.err();
  const double after =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
  EXPECT_EQ(bob.waitExit(1s), 0);
  EXPECT_EQ(bob.lastLine().rfind("result: win", 0), 0u) << bob.out();
  EXPECT_NE(bob.lastLine().find("forfeit"), std::string::npos) << bob.lastLine();
  recorder.pump(2s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return v && v->phase == MatchPhase::Over;
  });
  const MatchView* v = recorder.latest(recorder.firstMatch());
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->phase, MatchPhase::Over);
  EXPECT_EQ(v->end, rules::GameEnd::Forfeit);
  EXPECT_EQ(v->winner, seatOf(*v, "bob"));
  EXPECT_GE(after, 2.0 + 0.9 * 5.0) << "forfeited before the lease and the grace period ran out";
  std::printf("forfeited %.1f s after the kill\n", after);
}

}  // namespace
}  // namespace pool::client::test
