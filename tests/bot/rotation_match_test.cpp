// Two pool-bots play a 9-ball and a 10-ball race to 3 against pool-server --fast over loopback
// DDS; the server's stored shots, judged again rack by rack, give the same winner.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>

#include "game/loaded_table.h"
#include "server/store/match_audit.h"
#include "server/store/match_store.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

class RotationMatchTest : public ClientIntegrationTest {
 protected:
  ChildProcess& raceBot(const std::string& name, std::uint64_t seed) {
    return start("pool-bot",
                 {"--domain", std::to_string(domain_), "--name", name, "--skill", "0.9", "--seed",
                  std::to_string(seed), "--timeout", "500"},
                 name);
  }

  void playRace(Domain domain, const std::string& game, rules::Game expected) {
    open(domain, "race-" + game);
    MatchRecorder recorder(domain);
    ChildProcess& server = startServer({"--fast", "--game", game, "--race", "3", "--breaks",
                                        "winner", "--db", scratch_->file("pool.db")});
    ASSERT_TRUE(recorder.pump(20s, [&] {
      const std::string m = recorder.firstMatch();
      return !m.empty() && recorder.latest(m) != nullptr;
    })) << "the server's match never reached the recorder";
    const std::string match = recorder.firstMatch();
    const MatchView* lobby = recorder.latest(match);
    EXPECT_EQ(lobby->settings.game, expected);
    EXPECT_EQ(lobby->settings.race_to, 3);
    ChildProcess& alice = raceBot("alice", 11);
    ChildProcess& bob = raceBot("bob", 22);
    ASSERT_TRUE(recorder.waitForPlayers(2, 20s)) << "the bots' command writers never appeared";

    const auto begun = std::chrono::steady_clock::now();
    const bool ended = recorder.pump(
        480s, [&] { return stalledOnLayout(recorder) || (!alice.running() && !bob.running()); });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
    ASSERT_FALSE(stalledOnLayout(recorder)) << recorder.rejections().back().reject_text;
    ASSERT_TRUE(ended) << logs();
    EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
    EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
    const std::string a = alice.lastLine(), b = bob.lastLine();
    const bool alice_won = a.rfind("result: win", 0) == 0;
    EXPECT_TRUE((alice_won && b.rfind("result: loss", 0) == 0) ||
                (a.rfind("result: loss", 0) == 0 && b.rfind("result: win", 0) == 0))
        << a << " / " << b;

    recorder.pump(5s, [&] {
      const MatchView* v = recorder.latest(match);
      return v && v->phase == MatchPhase::Over;
    });
    const MatchView* final_state = recorder.latest(match);
    ASSERT_NE(final_state, nullptr);
    ASSERT_EQ(final_state->phase, MatchPhase::Over);
    const int winner = seatOf(*final_state, alice_won ? "alice" : "bob");
    EXPECT_EQ(final_state->winner, winner);
    ASSERT_TRUE(winner == 0 || winner == 1);
    EXPECT_EQ(final_state->seats[static_cast<std::size_t>(winner)].racks_won, 3);
    EXPECT_LT(final_state->seats[static_cast<std::size_t>(1 - winner)].racks_won, 3);
    EXPECT_GE(final_state->rack, 3u);

    // The server's stored shots, judged again by the rules engine, give every verdict, every
    // rack's winner and the same winner of the race.
    server.kill(SIGTERM);  // a clean stop lets go of the database file
    ASSERT_TRUE(server.waitExit(20s)) << "the server did not stop";
    auto store = store::MatchStore::open(scratch_->file("pool.db"));
    ASSERT_TRUE(store) << store.error();
    auto kit = game::loadSharedTable("wpa-9ft");
    ASSERT_TRUE(kit) << kit.error();
    const store::Audit audit = store::auditMatch(**store, match, **kit);
    for (const auto& problem : audit.problems) ADD_FAILURE() << match << ": " << problem;
    EXPECT_EQ(audit.shots, final_state->shot_number);
    EXPECT_EQ(audit.winner, final_state->winner);
    EXPECT_EQ(audit.racks[0], final_state->seats[0].racks_won);
    EXPECT_EQ(audit.racks[1], final_state->seats[1].racks_won);
    std::printf("%s race to 3, match %s: %d racks, %u shots (%u choices) in %.1f s; %s / %s\n",
                game.c_str(), match.c_str(), audit.racks[0] + audit.racks[1], audit.shots,
                audit.choices, seconds, a.c_str(), b.c_str());
  }
};

TEST_F(RotationMatchTest, TwoBotsPlayANineBallRaceToThree) {
  playRace(kNineBallRace, "9", rules::Game::NineBall);
}

TEST_F(RotationMatchTest, TwoBotsPlayATenBallRaceToThree) {
  playRace(kTenBallRace, "10", rules::Game::TenBall);
}

TEST_F(RotationMatchTest, TheFirstBotAtAFreeTableSetsHowItIsPlayed) {
  open(kOpensTable, "opens-table");
  MatchRecorder recorder(kOpensTable);
  startServer({"--fast"});  // the server's tables default to 8-ball, one rack, no clock
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  }));
  const std::string match = recorder.firstMatch();
  EXPECT_EQ(recorder.latest(match)->settings, protocol::MatchSettings{});
  start("pool-bot",
        {"--domain", std::to_string(domain_), "--name", "ada", "--game", "10", "--race", "2",
         "--breaks", "winner", "--shot-clock", "30", "--timeout", "60"},
        "ada");
  protocol::MatchSettings wanted;
  wanted.game = rules::Game::TenBall;
  wanted.race_to = 2;
  wanted.breaks = protocol::BreakOrder::Winner;
  wanted.shot_clock = 30.0;
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].name == "ada" && v->settings == wanted;
  })) << logs();
  // A 10-ball rack: ten object balls; the lobby shows the settings too.
  int object_balls = 0;
  for (const auto& b : recorder.latest(match)->balls) {
    object_balls += physics::onTable(b.state) && b.id != physics::kCueBall ? 1 : 0;
  }
  EXPECT_EQ(object_balls, 10);
  // A second bot with other wishes sits down and changes nothing.
  start("pool-bot",
        {"--domain", std::to_string(domain_), "--name", "bea", "--game", "8", "--timeout", "60"},
        "bea");
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[1].name == "bea";
  })) << logs();
  EXPECT_EQ(recorder.latest(match)->settings, wanted);
}

}  // namespace
}  // namespace pool::client::test
