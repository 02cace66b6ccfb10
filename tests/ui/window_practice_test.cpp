// A practice table played from the window under Xvfb against a real server over DDS: the
// scripted keys shoot, undo (the server's table back bit for bit), save a scenario pool-sim runs
// to the shot's events, and re-rack 9-ball.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <sstream>

#include "physics/events.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/xvfb_run.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

bool sameBalls(const std::vector<physics::Ball>& a, const std::vector<physics::Ball>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].id != b[i].id || a[i].state != b[i].state ||
        std::memcmp(a[i].pos.data(), b[i].pos.data(), 3 * sizeof(double)) != 0 ||
        std::memcmp(a[i].orient.coeffs().data(), b[i].orient.coeffs().data(), 4 * sizeof(double)) !=
            0) {
      return false;
    }
  }
  return true;
}

class WindowPracticeTest : public ClientIntegrationTest {
 protected:
  void SetUp() override {
    ClientIntegrationTest::SetUp();
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      POOL_NO_DISPLAY("xvfb-run is not installed");
    }
  }
};

TEST_F(WindowPracticeTest, KeysShootUndoSaveAndRerackAtAPracticeTable) {
  open(kWindowPractice, "window-practice");
  MatchRecorder recorder(kWindowPractice);
  startServer({"--fast"});
  const std::string saved = file("saved.json");
  std::ofstream(file("input.script")) << "wait aiming\n"
                                         "down SPACE\nframes 30\nup SPACE\n"
                                         "wait shot 1\nwait aiming\n"
                                         "down U\nup U\nframes 3\nwait aiming\n"
                                         "down F5\nup F5\nframes 3\n"
                                         "down 9\nup 9\nframes 3\nwait aiming\n"
                                         "frames 10\nquit\n";
  const std::string cmd = "timeout 150 " + pool::test::xvfbRun() +
                          " -s \"-screen 0 1280x720x24\" " + std::string(POOL_BIN_DIR) +
                          "/pool-client --domain " + std::to_string(domain_) +
                          " --json --timeout 120 --width 800 --height 450 --practice"
                          " --fresh-identity --practice-file " +
                          saved + " --script " + file("input.script") + " > " + file("window.out") +
                          " 2> " + file("window.err");
  auto window = std::async(std::launch::async, [cmd] { return std::system(cmd.c_str()); });

  // srv-1 is the server's free table; the window's "new" practice table is the next one.
  const std::string match = "srv-2";
  const bool racked = recorder.pump(120s, [&] {
    for (const auto& s : recorder.states(match)) {
      if (s.settings.practice && s.settings.game == rules::Game::NineBall) return true;
    }
    return false;
  });
  const int status = window.get();
  std::ifstream err_file(file("window.err"));
  std::stringstream err;
  err << err_file.rdbuf();
  ASSERT_TRUE(racked) << err.str() << logs();
  EXPECT_EQ(status, 0) << err.str();

  // The practice table's states: the rack, the shot, the undo (the rack again, bit for bit).
  const auto states = recorder.states(match);
  std::optional<MatchView> before_shot, after_shot, after_undo;
  for (const auto& s : states) {
    if (s.shot_number == 0 && !after_shot) before_shot = s;
    if (s.shot_number == 1 && !after_shot) after_shot = s;
    if (after_shot && s.shot_number == 1 && s.undo_depth == 0 && !after_undo) after_undo = s;
  }
  ASSERT_TRUE(before_shot && after_shot && after_undo);
  EXPECT_TRUE(before_shot->settings.practice);
  EXPECT_FALSE(sameBalls(before_shot->balls, after_shot->balls));
  EXPECT_TRUE(sameBalls(before_shot->balls, after_undo->balls));

  // F5 saved the table as it was (after the undo) and the shot: pool-sim gives its events.
  std::optional<ShotReport> stroke;
  for (const auto& r : recorder.reports()) {
    if (r.match == match && r.final() && !r.events.empty() && !stroke) stroke = r;
  }
  ASSERT_TRUE(stroke);
  const ShotReport& shot = *stroke;
  ChildProcess& sim = start("pool-sim", {saved}, "pool-sim");
  ASSERT_EQ(sim.waitExit(60s), 0) << sim.err();
  const auto result = nlohmann::json::parse(sim.out());
  const auto& events = result.at("events");
  ASSERT_EQ(events.size(), shot.events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(events[i].at("type").get<std::string>(), physics::toString(shot.events[i].type));
    EXPECT_NEAR(events[i].at("t").get<double>(), shot.events[i].t, 1e-9) << "event " << i;
  }
}

}  // namespace
}  // namespace pool::client::test
