// The windowed pool-client under Xvfb against a real server over DDS: scripted keys send the
// ShotCommands the controls promise and the server accepts them; a spectating window follows a
// bot match.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "client/app/aim.h"
#include "client/app/controls.h"
#include "support/client_fixture.h"
#include "support/display_check.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

class WindowClientTest : public ClientIntegrationTest {
 protected:
  void SetUp() override {
    ClientIntegrationTest::SetUp();
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      POOL_NO_DISPLAY("xvfb-run is not installed");
    }
  }

  /// Starts pool-client in a window under Xvfb (in the background) with `args` and `script`.
  void startWindow(const std::vector<std::string>& args, const std::string& script) {
    std::ofstream(file("input.script")) << script;
    std::string cmd = "timeout 150 xvfb-run -a -s \"-screen 0 1280x720x24\" " +
                      std::string(POOL_BIN_DIR) + "/pool-client --domain " +
                      std::to_string(domain_) + " --json --timeout 120 --width 800 --height 450" +
                      " --script " + file("input.script");
    for (const auto& a : args) cmd += " " + a;
    cmd += " > " + file("window.out") + " 2> " + file("window.err");
    window_ = std::async(std::launch::async, [cmd] { return std::system(cmd.c_str()); });
  }

  /// The window's exit status (waits for it).
  int windowExit() { return window_.valid() ? window_.get() : -1; }

  std::vector<nlohmann::json> windowLines(const std::string& event) const {
    std::vector<nlohmann::json> out;
    std::ifstream in(file("window.out"));
    for (std::string line; std::getline(in, line);) {
      auto json = nlohmann::json::parse(line, nullptr, false);
      if (!json.is_discarded() && json.value("event", "") == event) out.push_back(json);
    }
    return out;
  }

  std::string windowErr() const {
    std::ifstream in(file("window.err"));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::future<int> window_;
};

TEST_F(WindowClientTest, ScriptedKeysSendTheShotCommandsTheControlsPromise) {
  open(kWindowShot, "window-shot");
  MatchRecorder recorder(kWindowShot);
  startServer({"--fast"});
  // Left for 30 frames, A for 12, Space for 45 (1/60 s of input time per scripted frame).
  startWindow({"--hotseat", "--play"},
              "wait aiming\n"
              "down LEFT\nframes 30\nup LEFT\n"
              "down A\nframes 12\nup A\n"
              "down SPACE\nframes 45\nup SPACE\n"
              // The next shot, whoever's it is: tip raised for 20 frames, the call left automatic.
              "wait aiming\n"
              "down UP ctrl\nframes 20\nup UP\n"
              "down SPACE\nframes 30\nup SPACE\n"
              "frames 30\nquit\n");
  const app::ControlRates rates;
  const protocol::CommandLimits limits;
  std::string match;
  const protocol::ShotRequest* sent = nullptr;
  const protocol::ShotRequest* second = nullptr;
  const bool seen = recorder.pump(120s, [&] {
    match = recorder.firstMatch();
    const MatchView* v = recorder.latest(match);
    if (!v || v->breaker < 0) return false;
    sent = recorder.nthCommand(match, v->breaker, 1);
    second = recorder.nthCommand(match, v->breaker, 2);
    if (!second) second = recorder.nthCommand(match, 1 - v->breaker, 1);
    return sent && second && recorder.finals(match).size() >= 2;
  });
  const int status = windowExit();
  ASSERT_TRUE(seen) << "no accepted shot from the window\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();

  // The command on the wire: each control's effect at its documented rate.
  EXPECT_NEAR(sent->cue.yaw, 30.0 / 60.0 * rates.yaw, 1e-9);
  EXPECT_NEAR(sent->cue.elevation, 12.0 / 60.0 * rates.elevation, 1e-9);
  EXPECT_NEAR(sent->cue.speed, app::cueSpeedOf(45.0 / 60.0 / rates.charge_time, limits), 1e-9);
  EXPECT_FALSE(sent->cue.speed_is_ball);
  EXPECT_DOUBLE_EQ(sent->cue.tip_side, 0.0);
  EXPECT_DOUBLE_EQ(sent->cue.tip_height, 0.0);
  EXPECT_FALSE(sent->called_ball);  // the break needs no call
  ASSERT_TRUE(sent->cue_ball_at);   // the breaker has the cue ball in hand behind the head string
  EXPECT_LT(sent->cue_ball_at->x(), app::PlacementArea{}.head_string_x);

  // The next shot: the tip, the heading kept, and a call the rules accept (a ball and a pocket,
  // or a safety), with the cue ball placed legally if it is in hand.
  EXPECT_NEAR(second->cue.tip_height, 20.0 / 60.0 * rates.tip, 1e-9);
  EXPECT_DOUBLE_EQ(second->cue.tip_side, 0.0);
  EXPECT_DOUBLE_EQ(second->cue.yaw, sent->cue.yaw);
  EXPECT_NEAR(second->cue.speed, app::cueSpeedOf(30.0 / 60.0 / rates.charge_time, limits), 1e-9);
  EXPECT_NE(second->safety, second->called_ball.has_value());
  EXPECT_EQ(second->called_ball.has_value(), !second->called_pocket.empty());

  // The server took both: no rejection, and both verdicts came back.
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  EXPECT_GE(recorder.finals(match).size(), 2u);

  // The window said what it sent.
  const auto shots = windowLines("shot");
  ASSERT_EQ(shots.size(), 2u);
  EXPECT_NEAR(shots[0]["yaw"].get<double>(), sent->cue.yaw, 1e-12);
  EXPECT_NEAR(shots[1]["tip_height"].get<double>(), second->cue.tip_height, 1e-12);
}

TEST_F(WindowClientTest, ASpectatingWindowFollowsABotMatch) {
  open(kWindowSpectate, "window-spectate");
  MatchRecorder recorder(kWindowSpectate);
  startServer({"--fast"});
  startBot("alice", 5, {"--think", "0.25"});
  startBot("bob", 6, {"--think", "0.25"});
  constexpr int kShots = 3;
  startWindow({"--spectate", "any"}, "wait shot " + std::to_string(kShots) + "\nquit\n");
  const int status = windowExit();
  recorder.pump(10s, [] { return false; });
  ASSERT_EQ(status, 0) << (stalledOnLayout(recorder) ? "the bots' match stalled on a layout\n" : "")
                       << windowErr() << logs();

  const auto notes = windowLines("note");
  ASSERT_FALSE(notes.empty());
  // The first note after the server's key is pinned at first sight says what is watched.
  std::size_t first = 0;
  while (first + 1 < notes.size() && notes[first]["text"].get<std::string>().find(
                                         "pinned at first sight") != std::string::npos) {
    ++first;
  }
  EXPECT_EQ(notes[first]["text"].get<std::string>().rfind("watching ", 0), 0u);

  // Every state the window showed is one the server published, in order, up to the third shot.
  const auto states = windowLines("state");
  ASSERT_FALSE(states.empty());
  const std::string match = states[0]["match"];
  std::set<std::uint32_t> published;
  for (const auto& s : recorder.states(match)) published.insert(s.revision);
  std::uint32_t last_revision = 0, last_shot = 0;
  for (const auto& s : states) {
    EXPECT_EQ(s["match"], match);
    const auto revision = s["revision"].get<std::uint32_t>();
    EXPECT_TRUE(published.count(revision)) << revision;
    EXPECT_GE(revision, last_revision);
    last_revision = revision;
    last_shot = s["shot_number"].get<std::uint32_t>();
  }
  EXPECT_GE(last_shot, static_cast<std::uint32_t>(kShots));

  // It played the shots' motion back, and those shots were real ones.
  const auto motions = windowLines("motion");
  ASSERT_FALSE(motions.empty());
  const auto finals = recorder.finals(match);
  for (const auto& m : motions) {
    EXPECT_TRUE(finals.count(m["shot_number"].get<std::uint32_t>())) << m.dump();
  }
}

// A player whose window dies (SIGKILL) mid-match starts it again: the window finds its key and seat
// in the config folder, takes the seat back before the grace runs out, and plays on.
TEST_F(WindowClientTest, AWindowKilledMidMatchTakesItsSeatBackAndPlaysOn) {
  open(kWindowRestart, "window-restart");
  MatchRecorder recorder(kWindowRestart);
  startServer({"--grace", "60"});
  // The first window sits down and waits (it never shoots); then a bot takes the other seat.
  startWindow({"--play", "--name", "Wendy"}, "frames 100000\n");
  ASSERT_TRUE(recorder.pump(60s,
                            [&] {
                              const MatchView* v = recorder.latest(recorder.firstMatch());
                              return v && v->seats[0].name == "Wendy";
                            }))
      << windowErr() << logs();
  const std::string match = recorder.firstMatch();
  ChildProcess& bot = startBot("bert", 5);
  ASSERT_TRUE(recorder.pump(30s,
                            [&] {
                              const MatchView* v = recorder.latest(match);
                              return v && v->phase == MatchPhase::Break && v->shooter == 0;
                            }))
      << "the rack did not start with Wendy to break\n"
      << logs();
  // The window writes it when it reads the server's reply, which may be after the bot sat down.
  const std::string kept = file("config") + "/pool/players/Wendy.seat";
  ASSERT_TRUE(recorder.pump(10s, [&] { return std::ifstream(kept).good(); }))
      << "the window kept no seat file";

  // Killed: the server shows her away once her lease runs out.
  const std::string window = "^" + std::string(POOL_BIN_DIR) + "/pool-client --domain " +
                             std::to_string(domain_) + " ";  // the program, not xvfb-run
  ASSERT_EQ(std::system(("pkill -KILL -f '" + window + "'").c_str()), 0);
  windowExit();
  ASSERT_TRUE(recorder.pump(30s,
                            [&] {
                              const MatchView* v = recorder.latest(match);
                              return v && !v->seats[0].connected;
                            }))
      << "the server never showed the killed window away\n"
      << logs();

  // Started again with the same config folder: the seat comes back and the break is played.
  startWindow({"--play", "--name", "Wendy"},
              "wait aiming\ndown SPACE\nframes 40\nup SPACE\nframes 30\nquit\n");
  const bool back = recorder.pump(60s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].connected;
  });
  const bool played = back && recorder.pump(60s, [&] {
    return recorder.finals(match).size() >= 1 && recorder.nthCommand(match, 0, 1) != nullptr;
  });
  const int status = windowExit();
  ASSERT_TRUE(back) << "the restarted window did not take its seat back\n" << windowErr() << logs();
  ASSERT_TRUE(played) << "the restarted window did not break\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  bool said = false;
  for (const auto& note : windowLines("note")) {
    said = said || note.value("text", "").find("took back seat 1 in " + match) != std::string::npos;
  }
  EXPECT_TRUE(said) << "the window did not say it took its seat back";
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  EXPECT_EQ(recorder.latest(match)->seats[0].name, "Wendy");
  bot.kill(SIGTERM);
}

}  // namespace
}  // namespace pool::client::test
