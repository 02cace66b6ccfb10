// A spectating window under Xvfb draws the shooter's cue from the live aim: it moves while the
// shooter aims (a player of this test, through the client library and a real server), settles
// within 1 degree of the shooter's heading once they stop, and strokes at release.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "client/net/game_client.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/window_output.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

class LiveAimWindowTest : public ClientIntegrationTest {
 protected:
  void SetUp() override {
    ClientIntegrationTest::SetUp();
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      POOL_NO_DISPLAY("xvfb-run is not installed");
    }
  }
  void TearDown() override {
    if (window_.valid()) window_.wait();
  }

  void startSpectatingWindow(const std::string& match, const std::string& script) {
    std::ofstream(file("input.script")) << script;
    const std::string cmd = "timeout 150 xvfb-run -a -s \"-screen 0 1280x720x24\" " +
                            std::string(POOL_BIN_DIR) + "/pool-client --domain " +
                            std::to_string(domain_) +
                            " --json --log-frames --timeout 120 --width 800 --height 450" +
                            " --spectate " + match + " --script " + file("input.script") + " > " +
                            file("window.out") + " 2> " + file("window.err");
    window_ = std::async(std::launch::async, [cmd] { return std::system(cmd.c_str()); });
  }

  std::vector<nlohmann::json> windowLines(const std::string& event) const {
    return pool::test::jsonLines(file("window.out"), event);
  }

  std::string windowErr() const { return pool::test::fileText(file("window.err")); }

  std::future<int> window_;
};

/// The heading of the drawn cue (butt toward tip) in the table plane.
double drawnYaw(const nlohmann::json& stick) {
  const double dx = stick["tip"][0].get<double>() - stick["butt"][0].get<double>();
  const double dy = stick["tip"][1].get<double>() - stick["butt"][1].get<double>();
  return std::atan2(dy, dx);
}

double wrapped(double a) {
  return std::remainder(a, 2.0 * 3.14159265358979323846);
}

TEST_F(LiveAimWindowTest, TheSpectatorSeesTheShootersCueMoveAndSettleOnTheirAim) {
  open(kWindowLiveAim, "window-live-aim");
  startServer({});
  GameClient ada({kWindowLiveAim, "", "Ada", {}, {}});
  GameClient bob({kWindowLiveAim, "", "Bob", {}, {}});
  auto pump = [&](const std::function<bool()>& done, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      ada.poll();
      bob.poll();
      if (done()) return true;
      if (std::chrono::steady_clock::now() >= deadline) return false;
      ada.wait(10ms);
    }
  };
  // Requests go out once the server is seen (a request written before it is lost).
  ASSERT_TRUE(pump([&] { return ada.lobby().find("srv-1") && bob.lobby().find("srv-1"); }, 30s))
      << logs();
  ada.requestSeat("srv-1", 0);
  bob.requestSeat("srv-1", 1);
  ASSERT_TRUE(pump(
      [&] {
        const MatchView* v = ada.state("srv-1");
        return ada.seat() && bob.seat() && v && inPlay(v->phase) && v->shooter >= 0;
      },
      30s))
      << logs();
  const MatchView view = *ada.state("srv-1");
  GameClient& shooter = view.shooter == 0 ? ada : bob;
  Eigen::Vector2d cue_ball(-0.635, 0.0);
  for (const auto& b : view.balls) {
    if (b.id == physics::kCueBall) cue_ball = b.pos.head<2>();
  }

  startSpectatingWindow("srv-1", "wait shot 1\nframes 30\nquit\n");
  // The window follows the match once it printed its state.
  ASSERT_TRUE(pump([&] { return !windowLines("state").empty(); }, 60s)) << windowErr() << logs();

  auto aimAt = [&](double yaw, double power, bool stroke) {
    protocol::AimSample a;
    a.shot_number = view.shot_number;
    a.yaw = yaw;
    a.power = power;
    a.stroke = stroke;
    a.elevation = 2 * kDeg;
    a.cue_ball_x = cue_ball.x();
    a.cue_ball_y = cue_ball.y();
    return a;
  };
  // Aim: 1.2 s sweeping from -20 to +3 degrees at 30 Hz, then 1.5 s still (keep-alives).
  constexpr double kFrom = -20 * kDeg, kTo = 3 * kDeg;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t > 2.7) break;
    const double u = std::min(t / 1.2, 1.0);
    ASSERT_TRUE(shooter.sendAim(aimAt(kFrom + u * (kTo - kFrom), 0.0, false)));
    pump([] { return false; }, u < 1.0 ? 33ms : 200ms);
  }
  // The release: the stroke's aim, seen drawn, then the break itself.
  ASSERT_TRUE(shooter.sendAim(aimAt(kTo, 0.7, true)));
  const bool stroked = pump(
      [&] {
        for (const auto& d : windowLines("drawn")) {
          if (d.contains("cue_stick") && d["cue_stick"]["source"] == "stroke") return true;
        }
        return false;
      },
      30s);
  protocol::ShotRequest shot;
  shot.cue.yaw = kTo;
  shot.cue.speed = 6.0;
  ASSERT_TRUE(shooter.shoot(shot));
  const int status = window_.get();
  ASSERT_EQ(status, 0) << windowErr() << logs();
  EXPECT_TRUE(stroked) << "the window never drew the released cue's stroke";

  // The frames that drew the shooter's cue from the live aim.
  std::vector<nlohmann::json> remote;
  for (const auto& d : windowLines("drawn")) {
    if (d.contains("cue_stick") && d["cue_stick"]["source"] == "remote") remote.push_back(d);
  }
  ASSERT_GE(remote.size(), 20u) << windowErr();
  // It moved while they aimed: many frames, at many headings across the sweep, in order.
  std::set<int> tenths;  // headings drawn, to 0.1 degree
  double lowest = 10.0, highest = -10.0;
  for (const auto& d : remote) {
    const double yaw = drawnYaw(d["cue_stick"]);
    tenths.insert(static_cast<int>(std::lround(yaw / kDeg * 10)));
    lowest = std::min(lowest, yaw);
    highest = std::max(highest, yaw);
    // Drawn on screen: the tip inside the window.
    const double x = d["cue_stick"]["tip_px"][0].get<double>();
    const double y = d["cue_stick"]["tip_px"][1].get<double>();
    EXPECT_TRUE(x >= 0 && x <= d["width"].get<double>() && y >= 0 && y <= d["height"].get<double>())
        << d.dump();
  }
  EXPECT_GE(tenths.size(), 10u) << "the cue was drawn at few headings: it did not move";
  EXPECT_LT(lowest, -15 * kDeg) << "the sweep's start was drawn";
  EXPECT_GT(highest, 2 * kDeg) << "the sweep's end was drawn";

  // Once the shooter stopped: every frame drawn 0.5 s (window clock) after the window first
  // showed the final aim matches it within 1 degree.
  std::optional<double> final_since;
  int settled = 0;
  for (const auto& d : remote) {
    if (!d.contains("live_aim")) continue;
    if (std::abs(d["live_aim"]["yaw"].get<double>() - kTo) > 1e-12) continue;
    const double now = d["now"].get<double>();
    if (!final_since) final_since = now;
    if (now - *final_since < 0.5) continue;
    ++settled;
    EXPECT_LT(std::abs(wrapped(drawnYaw(d["cue_stick"]) - kTo)), 1 * kDeg) << d.dump();
  }
  EXPECT_GE(settled, 5) << "too few frames of the settled cue";

  // The spectator's Shot pane gave the shooter's aim in numbers, the settled one among them.
  bool numbers = false;
  for (const auto& hud : windowLines("hud")) {
    for (const auto& text : hud["texts"]) {
      numbers = numbers || text.get<std::string>() == "their aim 3.00 deg   cue elevation 2.0 deg";
    }
  }
  EXPECT_TRUE(numbers) << "the HUD never showed the shooter's settled aim";
  EXPECT_EQ(remote.back()["aim_dropped"].get<int>(), 0);
}

}  // namespace
}  // namespace pool::client::test
