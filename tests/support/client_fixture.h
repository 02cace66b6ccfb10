// Shared setup of the client integration tests: one DDS domain per test, the loopback config,
// and launchers for pool-server, pool-bot and pool-client.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "support/child_process.h"
#include "support/domain_claim.h"
#include "support/match_recorder.h"

namespace pool::client::test {

/// Client integration tests use DDS domains 200–219 and 120–134, one per test (ctest runs them in
/// parallel; net tests use 150–199, server tests 100–119).
enum Domain : std::uint32_t {
  kFullMatch = 200,
  kSpectator = 201,
  kRejoin = 202,
  kForfeit = 203,
  kCrash = 120,
  kReplay = 121,
  kWindowShot = 210,
  kWindowSpectate = 211,
  kWindowRestart = 212,
  kWindowNewGame = 213,
  kWindowBallInHand = 214,
  kRestarts = 122,
  kStarved = 136,  ///< 135–149: the signing, flood and presence tests
  kSpectateScreenshot = 204,
  // Server-signed samples and server ids (forged_sample_test, forged_match_test,
  // server_identity_test).
  kForgedSamples = 205,
  kImpossibleJumps = 206,
  kChangedKey = 207,
  kDuplicateId = 208,
  kForgedMatch = 209,
  kDatabaseCopy = 215,
  // Ways to play (nine_ball_race_test and the shot clock); 216 is the sound test's.
  kNineBallRace = 217,
  kTenBallRace = 218,
  kShotClock = 219,
  kOpensTable = 123,
  kThreeCushionGame = 130,
  kWindowThreeCushion = 131,
  kSnookerFrame = 132,
  kWindowSnooker = 133,
  kTournament = 134,
  kWebPage = 40,  ///< 40–59: the web spectator's tests and benchmark
  kWebGateway = 41,
  kWebSlowBrowser = 43,  ///< (42: web_bench)
  kWebLimits = 44,
  kWebConnectionFlood = 45,
  kWebLobbyFlood = 46,
  kWebPinFlood = 47,
  kWebSnookerPage = 48,
  kWebSnookerScore = 49,
  kWebSnookerLive = 50,
  kWebReplay = 51,
  kWebLook = 52,
  kWebLookMeter = 53,
  // Practice tables (practice_table_test): 90–99 are theirs.
  kPractice = 90,
  kPracticeAttacks = 91,
  kWindowPractice = 92,
  kPracticeRestart = 93,
  kPracticeFriend = 94,
  kPracticeSnooker = 95,
  kServerStopped = 60,  ///< 60–69: match partitions, a stopped server
  kPartitionSwitch = 61,
  // The shooter's live aim (live_aim_test, the window's and the benchmark's): 70–79.
  kLiveAim = 70,
  kForgedAim = 71,
  kWindowLiveAim = 72,
  kBotAim = 73,
};

/// A test with its own domain, scratch folder and processes (killed in teardown).
/// Sends volatile requests (seat and spectate requests) again every 2 s while their answers are
/// missing: one written before the server's reader matched its writer is lost (seen on a loaded
/// machine). Call it from a pump's predicate.
class Reask {
 public:
  void operator()(const std::function<void()>& ask) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::seconds(2)) return;
    ask();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_{};
};

class ClientIntegrationTest : public ::testing::Test {
 protected:
  void SetUp() override { useLoopbackConfig(); }

  void open(Domain domain, const std::string& tag) {
    domain_ = domain;
    pool::test::claimDomain(claim_, domain);
    pool::test::requireClaim(*claim_);
    scratch_ = std::make_unique<ScratchDir>(tag);
    // The servers' default database goes to the scratch folder, never the real home.
    ::setenv("XDG_DATA_HOME", scratch_->file("data").c_str(), 1);
    ::setenv("XDG_CONFIG_HOME", scratch_->file("config").c_str(), 1);  // windows keep keys there
  }

  ChildProcess& startServer(const std::vector<std::string>& extra) {
    std::vector<std::string> args{"--domain", std::to_string(domain_), "--tables",
                                  "1",        "--server-id",           "srv"};
    args.insert(args.end(), extra.begin(), extra.end());
    return start("pool-server", args, "server");
  }

  /// A bot named `name` with skill 0.8 (unless `extra` gives a --skill or --level) and `extra`
  /// flags; it gives up after 90 s.
  ChildProcess& startBot(const std::string& name, std::uint64_t seed,
                         const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{"--domain", std::to_string(domain_), "--name",    name,
                                  "--seed",   std::to_string(seed),    "--timeout", "90"};
    const bool strength_given = std::any_of(extra.begin(), extra.end(), [](const auto& arg) {
      return arg == "--skill" || arg == "--level";
    });
    if (!strength_given) args.insert(args.end(), {"--skill", "0.8"});
    args.insert(args.end(), extra.begin(), extra.end());
    return start("pool-bot", args, name + "-" + std::to_string(++runs_));
  }

  ChildProcess& startSpectator(const std::string& match) {
    return start("pool-client",
                 {"--domain", std::to_string(domain_), "--spectate", match, "--no-window", "--json",
                  "--timeout", "90"},
                 "spectator");
  }

  ChildProcess& start(const std::string& program, const std::vector<std::string>& args,
                      const std::string& tag) {
    processes_.push_back(std::make_unique<ChildProcess>(program, args, scratch_->file(tag + ".out"),
                                                        scratch_->file(tag + ".err")));
    return *processes_.back();
  }

  std::string file(const std::string& name) const { return scratch_->file(name); }

  /// The stderr of every process so far, for failure messages.
  std::string logs() const {
    std::string text;
    for (const auto& p : processes_) text += p->err().substr(0, 20000) + "\n----\n";
    return text;
  }

  /// The seat of the player called `name` in `view`, or -1.
  static int seatOf(const MatchView& view, const std::string& name) {
    for (int s = 0; s < 2; ++s) {
      if (view.seats[static_cast<std::size_t>(s)].name == name) return s;
    }
    return -1;
  }

  /// True when the server keeps refusing shots because the physics refuses the layout it left
  /// (a ball at rest in a pocket mouth): the match cannot go on.
  static bool stalledOnLayout(const MatchRecorder& recorder) {
    int refused = 0;
    for (const auto& r : recorder.rejections()) {
      refused += r.reject_text.find("the physics refused") != std::string::npos ? 1 : 0;
    }
    return refused >= 3;
  }

  /// Where the balls on the table lie in the latest state of `match` (for a stall's message).
  static std::string layoutOf(const MatchRecorder& recorder, const std::string& match) {
    std::string text;
    const MatchView* v = recorder.latest(match);
    if (!v) return text;
    char line[96];
    for (const auto& b : v->balls) {
      if (!physics::onTable(b.state)) continue;
      std::snprintf(line, sizeof line, "ball %d at (%.5f, %.5f)\n", b.id, b.pos.x(), b.pos.y());
      text += line;
    }
    return text;
  }

  Domain domain_ = kFullMatch;
  std::unique_ptr<pool::test::DomainClaim> claim_;
  std::unique_ptr<ScratchDir> scratch_;
  std::vector<std::unique_ptr<ChildProcess>> processes_;  // destroyed first: children killed
  int runs_ = 0;
};

}  // namespace pool::client::test
