// A club night's tournament from end to end: eight bots enter a single-elimination tournament of
// races to 1 that the operator creates, the server runs it (tables opened as matches are drawn,
// seats reserved for the drawn keys), is killed with SIGKILL in the middle and started again on
// its file, and the tournament goes on to one champion; afterwards the bracket, the store and the
// ratings agree.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <map>
#include <set>
#include <thread>

#include "server/store/rating_book.h"
#include "server/store/tournament_book.h"
#include "server/tournament/tournament.h"
#include "support/client_fixture.h"
#include "support/match_recorder.h"

namespace pool::client::test {
namespace {

class TournamentTest : public ClientIntegrationTest {
 protected:
  ChildProcess& startNumberedServer() {
    ++runs_;
    std::vector<std::string> args{"--domain",     std::to_string(domain_),
                                  "--tables",     "1",
                                  "--server-id",  "srv",
                                  "--fast",       "--grace",
                                  "60",           "--db",
                                  file("pool.db")};
    return start("pool-server", args, "server" + std::to_string(runs_));
  }

  /// The tournament as the recorder's client last received it, or null.
  const protocol::TournamentView* bracket(const MatchRecorder& recorder) const {
    const auto& all = recorder.client().tournaments();
    const auto it = all.find("srv-t1");
    return it == all.end() ? nullptr : &it->second;
  }

  static int decided(const protocol::TournamentView& v) {
    int n = 0;
    for (const auto& m : v.matches) n += m.state == 3 ? 1 : 0;
    return n;
  }

  int runs_ = 0;
};

// Time bound: the tournament ends within 150 s of the bots' entries (about 15 s measured plain:
// seven racks of club bots with frames unpaced; the bound leaves the sanitizers' slowdown room).
TEST_F(TournamentTest, EightBotsPlayASingleEliminationThroughAServerKillToOneChampion) {
  open(kTournament, "tournament");
  MatchRecorder recorder(kTournament);
  ChildProcess* server = &startNumberedServer();
  // The operator creates it (pool-server admin, over the server's socket beside its file, once
  // the server has opened it).
  std::optional<int> created;
  for (int attempt = 0; attempt < 100 && created != 0; ++attempt) {
    if (attempt) std::this_thread::sleep_for(200ms);
    created = start("pool-server",
                    {"admin", "--db", file("pool.db"), "tournament-create", "Club night",
                     "--format", "single", "--game", "8", "--race", "1", "--entrants", "8"},
                    "admin")
                  .waitExit(20s);
  }
  ASSERT_EQ(created, 0) << logs();
  std::vector<ChildProcess*> bots;
  const std::vector<std::string> names{"ann", "bob", "cid", "dot", "eve", "fay", "gus", "hal"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::vector<std::string> args{"--domain",     std::to_string(domain_),
                                  "--name",       names[i],
                                  "--seed",       std::to_string(31 + i),
                                  "--timeout",    "200",
                                  "--skill",      "1",
                                  "--tournament", "srv-t1"};
    bots.push_back(&start("pool-bot", args, names[i]));
  }
  const auto entered = std::chrono::steady_clock::now();

  // Killed once the first round is under way and at least one of its matches is decided: a
  // match in play goes down with the server.
  ASSERT_TRUE(recorder.pump(90s,
                            [&] {
                              const auto* v = bracket(recorder);
                              return v && decided(*v) >= 1 && decided(*v) < 7;
                            }))
      << "the tournament never got under way\n"
      << logs();
  server->kill(SIGKILL);
  server = &startNumberedServer();

  const auto* finished = static_cast<const protocol::TournamentView*>(nullptr);
  ASSERT_TRUE(recorder.pump(150s,
                            [&] {
                              finished = bracket(recorder);
                              return finished &&
                                     finished->phase == protocol::TournamentPhase::Finished;
                            }))
      << "no champion within the bound\n"
      << logs();
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - entered).count();
  std::printf("tournament of 8 with a server kill: %.1f s from the entries to the champion\n",
              took);
  const protocol::TournamentView view = *finished;

  // The bracket: eight entrants seeded 1..8, seven matches each decided at a table of its own
  // (never by forfeit: everyone came back after the kill), one champion, places 1, 2, 3, 3 and
  // four 5ths.
  ASSERT_EQ(view.entrants.size(), 8u);
  ASSERT_EQ(view.matches.size(), 7u);
  std::set<std::string> tables;
  for (const auto& m : view.matches) {
    EXPECT_EQ(m.state, 3) << m.round;
    EXPECT_FALSE(m.forfeit) << m.round << " at " << m.match;
    EXPECT_TRUE(m.winner == m.a || m.winner == m.b) << m.round;
    EXPECT_EQ(m.winner == m.a ? m.racks_a : m.racks_b, 1) << m.round;
    EXPECT_FALSE(m.match.empty()) << m.round;
    tables.insert(m.match);
  }
  EXPECT_EQ(tables.size(), 7u) << "each match at a table of its own";
  ASSERT_GE(view.champion, 0);
  std::map<int, int> places;
  std::set<int> seeds;
  for (const auto& e : view.entrants) {
    ++places[e.place];
    seeds.insert(e.seed);
  }
  EXPECT_EQ(places, (std::map<int, int>{{1, 1}, {2, 1}, {3, 2}, {5, 4}}));
  EXPECT_EQ(seeds, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(view.entrants[static_cast<std::size_t>(view.champion)].place, 1);

  // Every bot ends with the tournament (the champion says so).
  for (std::size_t i = 0; i < bots.size(); ++i) {
    EXPECT_EQ(bots[i]->waitExit(30s), 0) << names[i] << "\n" << logs();
    const std::string line = bots[i]->lastLine();
    EXPECT_NE(line.find("tournament srv-t1 finished"), std::string::npos)
        << names[i] << ": " << line;
    if (names[i] == view.entrants[static_cast<std::size_t>(view.champion)].name) {
      EXPECT_NE(line.find("champion (3 matches won)"), std::string::npos) << line;
    }
  }

  // The store, once the server stops: the tournament finished with the same bracket (its
  // stored state restores to the same champion), and each of its seven matches rated once,
  // the winner up and the loser down.
  server->kill(SIGTERM);
  ASSERT_TRUE(server->waitExit(20s)) << "the server did not stop";
  auto store = store::MatchStore::open(file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  const auto row = store::tournament((*store)->database(), "srv-t1");
  ASSERT_TRUE(row);
  EXPECT_EQ(row->phase, static_cast<int>(protocol::TournamentPhase::Finished));
  auto restored = tournament::Tournament::fromJson(row->state);
  ASSERT_TRUE(restored) << restored.error();
  ASSERT_TRUE(restored->champion());
  EXPECT_EQ(*restored->champion(), view.champion);
  for (const auto& m : view.matches) {
    const auto rated = store::ratedResults((*store)->database(), m.match);
    ASSERT_EQ(rated.size(), 1u) << m.match << " was not rated once";
    EXPECT_GT(rated[0].winner_after, rated[0].winner_before) << m.match;
    EXPECT_LT(rated[0].loser_after, rated[0].loser_before) << m.match;
  }
}

}  // namespace
}  // namespace pool::client::test
