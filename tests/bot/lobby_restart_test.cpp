// pool-server restarted five times, each time cut off in the middle of a bot game whose players
// never come back: the lobby keeps only live and free tables (no game between absent players,
// none "won" by one of them), two bots started together meet at one table, and with --tables 1
// game follows game.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "server/store/match_store.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

class LobbyRestartTest : public ClientIntegrationTest {
 protected:
  ChildProcess& startServerRun(int run) {
    return start("pool-server",
                 {"--domain", std::to_string(domain_), "--tables", "1", "--server-id", "srv",
                  "--fast", "--grace", "2", "--db", file("pool.db")},
                 "server" + std::to_string(run));
  }

  /// The lobby as the recorder sees it: "<match> <phase> <players>" per entry.
  static std::string lobbyText(const MatchRecorder& recorder) {
    std::string out;
    for (const LobbyEntry* e : recorder.client().lobby().entries()) {
      out += e->match + " " + std::string(toString(e->phase)) + " [" + e->players[0] + "|" +
             e->players[1] + "]\n";
    }
    return out;
  }

  /// The states of every match a ghost sat at, by match.
  static std::map<std::string, std::vector<MatchView>> ghostStates(const MatchRecorder& recorder) {
    std::map<std::string, std::vector<MatchView>> out;
    for (const auto& r : recorder.reports()) {
      if (out.count(r.match)) continue;
      const auto states = recorder.states(r.match);
      for (const auto& st : states) {
        if (st.seats[0].name.rfind("ghost-", 0) == 0) {
          out[r.match] = states;
          break;
        }
      }
    }
    return out;
  }

  /// The match both `a` and `b` sit at, or "".
  static std::string matchOf(const MatchRecorder& recorder, const std::string& a,
                             const std::string& b) {
    for (const LobbyEntry* e : recorder.client().lobby().entries()) {
      const std::set<std::string> players{e->players[0], e->players[1]};
      if (players == std::set<std::string>{a, b}) return e->match;
    }
    return {};
  }

  /// Starts two bots at once and waits for them to play their game to its end: both exit with
  /// 0, one won and one lost, and they sat at one table.
  void playAGame(MatchRecorder& recorder, const std::string& a, const std::string& b,
                 std::uint64_t seed) {
    ChildProcess& one = startBot(a, seed, {"--think", "0"});
    ChildProcess& two = startBot(b, seed + 1, {"--think", "0"});
    std::string match;
    ASSERT_TRUE(recorder.pump(30s, [&] { return !(match = matchOf(recorder, a, b)).empty(); }))
        << a << " and " << b << " did not sit at one table:\n"
        << lobbyText(recorder) << logs();
    ASSERT_TRUE(recorder.pump(100s, [&] { return !one.running() && !two.running(); })) << logs();
    EXPECT_EQ(one.waitExit(1s), 0) << one.err();
    EXPECT_EQ(two.waitExit(1s), 0) << two.err();
    const std::string la = one.lastLine(), lb = two.lastLine();
    EXPECT_TRUE((la.rfind("result: win", 0) == 0 && lb.rfind("result: loss", 0) == 0) ||
                (la.rfind("result: loss", 0) == 0 && lb.rfind("result: win", 0) == 0))
        << match << ": " << la << " / " << lb;
  }
};

TEST_F(LobbyRestartTest, FiveRestartsLeaveOnlyLiveAndFreeTablesAndGameFollowsGame) {
  open(kRestarts, "restarts");
  MatchRecorder recorder(kRestarts);
  for (int run = 1; run <= 5; ++run) {
    ChildProcess& server = startServerRun(run);
    const std::string n = std::to_string(run);
    ChildProcess& a = startBot("ghost-a" + n, 100 + static_cast<std::uint64_t>(run));
    ChildProcess& b = startBot("ghost-b" + n, 200 + static_cast<std::uint64_t>(run));
    // This run's own game under way: its two ghosts at one table, a shot played there (an
    // earlier run's result, handed over again by the restarted server, does not count).
    ASSERT_TRUE(recorder.pump(60s,
                              [&] {
                                const std::string match =
                                    matchOf(recorder, "ghost-a" + n, "ghost-b" + n);
                                const MatchView* v =
                                    match.empty() ? nullptr : recorder.latest(match);
                                return v && v->shot_number >= 1;
                              }))
        << "run " << run << ": no game started\n"
        << lobbyText(recorder) << logs();
    // Cut off mid-game: the players are gone for good, then the server is killed.
    a.kill(SIGKILL);
    b.kill(SIGKILL);
    server.kill(SIGKILL);
    server.waitExit(5s);
  }
  startServerRun(6);

  // The five resumed games wait out their players' grace, then close: one free table remains.
  const auto onlyOneFreeTable = [&] {
    const auto entries = recorder.client().lobby().entries();
    return entries.size() == 1 && entries[0]->phase == MatchPhase::Lobby &&
           entries[0]->seats_taken == 0;
  };
  EXPECT_TRUE(recorder.pump(60s, onlyOneFreeTable)) << "the lobby after five restarts:\n"
                                                    << lobbyText(recorder) << logs();
  for (const LobbyEntry* e : recorder.client().lobby().entries()) {
    EXPECT_NE(e->phase, MatchPhase::Over) << e->match << " ended between absent players";
  }
  for (const auto& [match, states] : ghostStates(recorder)) {
    for (const auto& state : states) {
      EXPECT_NE(state.phase, MatchPhase::Over)
          << match << " got a result although nobody came back to it";
    }
  }

  // Two bots started together play each other; then the next two get a table too.
  playAGame(recorder, "ada", "bob", 11);
  playAGame(recorder, "cy", "di", 31);

  // What the server stored agrees: each of the five runs' games is there, between its ghosts,
  // closed without a winner. (The store, not the recorder, counts them: a recorder on a loaded
  // machine may join a run's match too late to see its seats.)
  for (auto& p : processes_) {  // the last server holds the file's lock until it ends
    p->kill(SIGKILL);
    p->waitExit(5s);
  }
  auto store = store::MatchStore::open(file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  std::set<std::string> runs_stored;
  for (const auto& stored : (*store)->matches()) {
    const std::string& first = stored.seats[0].player;
    const std::string& second = stored.seats[1].player;
    if (first.rfind("ghost-", 0) != 0 && second.rfind("ghost-", 0) != 0) continue;
    const std::string run = (first.rfind("ghost-", 0) == 0 ? first : second).substr(7);
    runs_stored.insert(run);
    EXPECT_TRUE(stored.closed) << stored.id << " of run " << run;
    EXPECT_EQ(stored.game.winner, -1) << stored.id << " was stored with a winner";
  }
  EXPECT_EQ(runs_stored, (std::set<std::string>{"1", "2", "3", "4", "5"}));
  for (const auto& [match, states] : ghostStates(recorder)) {
    const auto stored = (*store)->match(match);
    ASSERT_TRUE(stored) << match << " seen by the recorder is not stored";
  }
}

}  // namespace
}  // namespace pool::client::test
