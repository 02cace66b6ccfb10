// pool-server killed with SIGKILL at random moments of bot matches, at least 20 times, and started
// again on the same database each time: no accepted shot is lost, no match is corrupted, and each
// match ends with the winner the rules engine gives for its stored shots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <regex>
#include <set>
#include <tuple>

#include "game/loaded_table.h"
#include "server/store/match_audit.h"
#include "server/store/match_store.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

constexpr int kKills = 20;

class ServerCrashTest : public ClientIntegrationTest {
 protected:
  /// Starts two bots that keep their seats in token files; they find the lowest free table.
  void startPair() {
    ++pair_;
    const std::string n = std::to_string(pair_);
    for (const std::string& name : {"alice" + n, "bob" + n}) {
      bots_.push_back(&startBot(name, static_cast<std::uint64_t>(bots_.size() + 11),
                                {"--think", "0.05", "--token-file", file(name + ".json")}));
    }
  }

  bool pairDone() {
    return bots_.size() >= 2 && !bots_[bots_.size() - 1]->running() &&
           !bots_[bots_.size() - 2]->running();
  }

  std::size_t acceptedSeen(const MatchRecorder& recorder) const {
    return static_cast<std::size_t>(std::count_if(recorder.reports().begin(),
                                                  recorder.reports().end(),
                                                  [](const auto& r) { return r.accepted; }));
  }

  /// The commit times the servers logged ("stored shot N of M (...) in X ms"), ms.
  std::vector<double> commitTimes() const {
    std::vector<double> out;
    static const std::regex kLine(R"(stored shot \d+ of \S+ \(seat \d seq \d+\) in ([0-9.]+) ms)");
    for (int run = 1; run <= restarts_ + 1; ++run) {
      std::ifstream in(file("server" + std::to_string(run) + ".err"));
      std::string line;
      std::smatch m;
      while (std::getline(in, line)) {
        if (std::regex_search(line, m, kLine)) out.push_back(std::stod(m[1]));
      }
    }
    return out;
  }

  ChildProcess& startNumberedServer(const std::vector<std::string>& extra) {
    std::vector<std::string> args{"--domain", std::to_string(domain_), "--tables",
                                  "1",        "--server-id",           "srv"};
    args.insert(args.end(), extra.begin(), extra.end());
    return start("pool-server", args, "server" + std::to_string(restarts_ + 1));
  }

  int pair_ = 0;
  int restarts_ = 0;
  std::vector<ChildProcess*> bots_;
};

TEST_F(ServerCrashTest, KilledAtRandomMomentsTheMatchesLoseNoShotAndEndAsTheRulesSay) {
  open(kCrash, "crash");
  MatchRecorder recorder(kCrash);
  const std::vector<std::string> server_args{"--fast", "--grace", "120", "--db", file("pool.db")};
  ChildProcess* server = &startNumberedServer(server_args);
  const unsigned seed = std::random_device{}();
  std::printf("kill moments from seed %u\n", seed);
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> delay_ms(0, 400);
  startPair();

  // Each kill comes a random moment after the match made progress on the new server.
  int kills = 0;
  bool stalled = false;
  // The match whose shots the server refused last (the one a stall is in).
  const auto stalledMatch = [&recorder] {
    const auto refused = recorder.rejections();
    return refused.empty() ? std::string() : refused.back().match;
  };
  while (kills < kKills && !stalled) {
    if (pairDone()) startPair();
    const std::size_t before = acceptedSeen(recorder);
    ASSERT_TRUE(recorder.pump(
        60s,
        [&] { return acceptedSeen(recorder) > before || pairDone() || stalledOnLayout(recorder); }))
        << "no progress after kill " << kills << "\n"
        << logs();
    stalled = stalledOnLayout(recorder);
    if (pairDone() || stalled) continue;
    recorder.pump(std::chrono::milliseconds(delay_ms(random)));
    server->kill(SIGKILL);
    ++kills;
    ++restarts_;
    server = &startNumberedServer(server_args);
  }
  ASSERT_FALSE(stalled) << "a match stalled after " << kills
                        << " kills: the server refused shots because the physics refused the "
                           "layout it had left\n"
                        << layoutOf(recorder, stalledMatch()) << logs();

  // The last match plays out undisturbed, then the server stops cleanly.
  ASSERT_TRUE(recorder.pump(90s, [&] { return pairDone() || stalledOnLayout(recorder); }))
      << logs();
  ASSERT_FALSE(stalledOnLayout(recorder))
      << "the last match stalled: the server refused shots because the physics refused the "
         "layout it had left\n"
      << layoutOf(recorder, stalledMatch()) << logs();
  recorder.pump(1s);
  server->kill(SIGTERM);
  ASSERT_EQ(server->waitExit(10s), 0) << server->err();

  // Every shot anyone saw accepted is stored, under the number it was accepted with.
  auto store = store::MatchStore::open(file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  auto kit = game::loadSharedTable("wpa-9ft");
  ASSERT_TRUE(kit) << kit.error();
  std::set<std::string> matches;
  std::set<std::tuple<std::string, int, std::uint32_t, std::uint32_t>> stored;
  for (const auto& r : recorder.reports()) {
    if (r.accepted) matches.insert(r.match);
  }
  for (const auto& id : matches) {
    for (const auto& s : (*store)->shots(id)) {
      stored.insert({id, s.record.command.seat, s.record.command.seq, s.record.shot_number});
    }
  }
  std::size_t observed = 0;
  for (const auto& r : recorder.reports()) {
    if (!r.accepted) continue;
    ++observed;
    EXPECT_TRUE(stored.count({r.match, r.seat, r.seq, r.shot_number}))
        << r.match << " seat " << r.seat << " seq " << r.seq << " shot " << r.shot_number
        << " was accepted but is not stored";
  }

  // Every match re-judges to its stored verdicts, without gaps, and ends with the rules' winner.
  std::uint32_t shots = 0;
  for (const auto& id : matches) {
    const store::Audit audit = store::auditMatch(**store, id, **kit);
    shots += audit.shots;
    for (const auto& problem : audit.problems) ADD_FAILURE() << id << ": " << problem;
    const auto match = (*store)->match(id);
    ASSERT_TRUE(match);
    EXPECT_EQ(match->game.phase, rules::Phase::Over) << id << " did not finish";
    EXPECT_EQ(match->game.winner, audit.winner) << id;
    const MatchView* seen = recorder.latest(id);
    ASSERT_NE(seen, nullptr);
    EXPECT_EQ(seen->winner, audit.winner) << id << ": the players saw another winner";
  }
  EXPECT_GE(kills, kKills);
  for (auto* bot : bots_) {
    EXPECT_EQ(bot->waitExit(1s), 0) << bot->err();
    EXPECT_EQ(bot->lastLine().rfind("result: ", 0), 0u) << bot->out();
  }

  const auto times = commitTimes();
  double sum = 0, worst = 0;
  for (double t : times) {
    sum += t;
    worst = std::max(worst, t);
  }
  std::printf(
      "%d kills survived, %zu matches, %u stored shots re-judged, %zu accepted results "
      "checked; commit per shot: mean %.2f ms, max %.2f ms over %zu commits\n",
      kills, matches.size(), shots, observed,
      times.empty() ? 0.0 : sum / static_cast<double>(times.size()), worst, times.size());
}

}  // namespace
}  // namespace pool::client::test
