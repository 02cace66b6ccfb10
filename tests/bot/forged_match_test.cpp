// Two bots and a spectator play and watch a match while an adversary on the domain publishes a
// forged MatchState (over, revision 0xfffffff0), a forged TableSnapshot (shot 0xffffffff) and
// forged ShotResults (game over), unsigned and signed by another key: each is dropped with a log
// line, and the match ends as it is played.
#include <gtest/gtest.h>

#include <optional>
#include <utility>
#include <vector>

#include "support/client_fixture.h"
#include "support/forger.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

class ForgedMatchTest : public ClientIntegrationTest {};

TEST_F(ForgedMatchTest, BotsAndASpectatorIgnoreForgedSamplesAndFinishTheRealMatch) {
  open(kForgedMatch, "forged-match");
  MatchRecorder recorder(kForgedMatch);
  startServer({"--fast"});
  ASSERT_TRUE(recorder.pump(20s, [&] { return recorder.latest("srv-1") != nullptr; })) << logs();
  ChildProcess& alice = startBot("alice", 31, {"--think", "0.3"});
  ChildProcess& bob = startBot("bob", 32, {"--think", "0.3"});
  ChildProcess& spectator = startSpectator("srv-1");
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest("srv-1");
    return stalledOnLayout(recorder) || (v && v->shot_number >= 1);
  })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder));

  // Mid-match, while both bots and the spectator follow it.
  pool::test::Forger forger(kForgedMatch);
  forger.expectReaders(4);  // the recorder, both bots and the spectator
  const std::uint32_t shots = recorder.latest("srv-1")->shot_number;
  // Unsigned first, then signed by another key. States and results are keep-last 1: each round
  // waits until every client logged its drop, so the second does not replace the first unseen.
  const std::vector<std::pair<std::optional<protocol::KeyPair>, std::string>> rounds{
      {std::nullopt, "dropped: unsigned"},
      {protocol::generateKeyPair(), "but the key pinned for that server is"}};
  for (const auto& round : rounds) {
    const std::string& line = round.second;  // a plain name: clang 14 cannot capture bindings
    forger.signWith(round.first);
    ASSERT_TRUE(forger.publishState("srv-1", 0xfffffff0u, shots));
    ASSERT_TRUE(forger.publishFrame("srv-1", 0xffffffffu));
    ASSERT_TRUE(forger.publishResult("srv-1", 0, shots + 1));
    ASSERT_TRUE(forger.publishResult("srv-1", 1, shots + 1));
    EXPECT_TRUE(recorder.pump(30s,
                              [&] {
                                for (ChildProcess* p : {&alice, &bob, &spectator}) {
                                  if (p->err().find(line) == std::string::npos) return false;
                                }
                                return true;
                              }))
        << line << "\n"
        << logs();
  }

  const bool ended = recorder.pump(
      120s, [&] { return stalledOnLayout(recorder) || (!alice.running() && !bob.running()); });
  ASSERT_FALSE(stalledOnLayout(recorder));
  ASSERT_TRUE(ended) << logs();
  EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
  EXPECT_EQ(spectator.waitExit(30s), 0) << spectator.err();

  // The real end: one winner, after the shots the server counted, not the forged forfeit.
  recorder.pump(5s, [&] { return recorder.latest("srv-1")->phase == MatchPhase::Over; });
  const MatchView* final_state = recorder.latest("srv-1");
  ASSERT_EQ(final_state->phase, MatchPhase::Over);
  EXPECT_LT(final_state->revision, 0xfffffff0u);
  EXPECT_NE(final_state->end, rules::GameEnd::Forfeit);
  EXPECT_GT(final_state->shot_number, shots);
  const std::string a = alice.lastLine(), b = bob.lastLine();
  const std::string after = "after " + std::to_string(final_state->shot_number) + " shots";
  EXPECT_NE(a.find(after), std::string::npos) << a;
  EXPECT_NE(b.find(after), std::string::npos) << b;
  EXPECT_TRUE((a.rfind("result: win", 0) == 0 && b.rfind("result: loss", 0) == 0) ||
              (a.rfind("result: loss", 0) == 0 && b.rfind("result: win", 0) == 0))
      << a << " / " << b;

  // Nothing forged reached the spectator's output.
  EXPECT_EQ(spectator.out().find("4294967280"), std::string::npos);
  EXPECT_EQ(spectator.out().find("4294967295"), std::string::npos);
  EXPECT_EQ(spectator.out().find("forged"), std::string::npos);
}

}  // namespace
}  // namespace pool::client::test
