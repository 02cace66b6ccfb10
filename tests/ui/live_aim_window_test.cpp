// A spectating window under Xvfb draws the shooter's cue from the live aim: it moves while the
// shooter aims (a player of this test, through the client library and a real server), is drawn
// in the captured pixels along the shooter's line once they stop, and strokes at release.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <future>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "client/net/game_client.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/window_output.h"
#include "support/xvfb_run.h"
#include "table/table_spec.h"

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
    const std::string cmd = "timeout 150 " + pool::test::xvfbRun() +
                            " -s \"-screen 0 1280x720x24\" " + std::string(POOL_BIN_DIR) +
                            "/pool-client --domain " + std::to_string(domain_) +
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

/// The frame's camera as its drawn line reports it.
ReportedCamera cameraOf(const nlohmann::json& drawn) {
  ReportedCamera camera;
  camera.width = drawn["width"];
  camera.height = drawn["height"];
  camera.view = matrixOf(drawn["view"]);
  camera.projection = matrixOf(drawn["projection"]);
  return camera;
}

/// Maple, the cue's shaft: a warm light wood, red over green over blue.
bool isMaple(const Rgb& p) {
  return p[0] > 90 && p[0] > p[1] && p[1] > p[2] && p[0] - p[2] > 45;
}

/// The cloth: green over red and blue.
bool isFelt(const Rgb& p) {
  return p[1] > 40 && p[1] > p[0] + 20 && p[1] > p[2] + 10;
}

/// Share of the points s metres behind the cue ball's centre along a cue aimed at `yaw` and
/// `elevation` (s from `s0` to `s1` in 1 cm steps, those inside the image) that show maple (or
/// `colour`) within 1.5 px. The cue's axis, as common/physics/cue_strike.cpp strikes the centre (no
/// tip offset): the centre minus s·d, d = (cos θ cos ψ, cos θ sin ψ, −sin θ).
double mapleShare(const Image& image, const ReportedCamera& camera, glm::dvec3 centre, double yaw,
                  double elevation, double s0, double s1, int* seen = nullptr,
                  bool (*colour)(const Rgb&) = isMaple) {
  const glm::dvec3 d(std::cos(elevation) * std::cos(yaw), std::cos(elevation) * std::sin(yaw),
                     -std::sin(elevation));
  int inside = 0, wood = 0;
  for (double s = s0; s <= s1; s += 0.01) {
    const glm::vec3 px = camera.pixel(glm::vec3(centre - d * s));
    if (!camera.inside(px)) continue;
    ++inside;
    if (countInDisc(image, px.x, px.y, 1.5, colour) > 0) ++wood;
  }
  if (seen) *seen = inside;
  return inside ? double(wood) / inside : 0.0;
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
  Reask reask;
  ASSERT_TRUE(pump(
      [&] {
        const MatchView* v = ada.state("srv-1");
        if (ada.seat() && bob.seat() && v && inPlay(v->phase) && v->shooter >= 0) return true;
        reask([&] {
          if (!ada.seat()) ada.requestSeat("srv-1", 0);
          if (!bob.seat()) bob.requestSeat("srv-1", 1);
        });
        return false;
      },
      30s))
      << logs();
  const MatchView view = *ada.state("srv-1");
  GameClient& shooter = view.shooter == 0 ? ada : bob;
  Eigen::Vector2d cue_ball(-0.635, 0.0);
  for (const auto& b : view.balls) {
    if (b.id == physics::kCueBall) cue_ball = b.pos.head<2>();
  }

  // The window captures a frame every kCaptureEvery frames from its start, kCaptures of them:
  // 576 frames, 4 s at the window's fastest (144 a second), over the 2.5 s (window clock) it takes
  // to show the sweep and settle (below), then follows the break.
  constexpr int kCaptures = 16, kCaptureEvery = 36;
  std::string script;
  for (int i = 0; i < kCaptures; ++i) {
    script += "capture " + file("frame-" + std::to_string(i) + ".png") + "\nframes " +
              std::to_string(kCaptureEvery) + "\n";
  }
  startSpectatingWindow("srv-1", script + "wait shot 1\nframes 30\nquit\n");
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
  // A captured frame drawn kSettled s (window clock) or more after the window first showed the
  // final aim: the remote cue eases toward the aim it received and is within 1 degree of it 0.5 s
  // on (the logged heading showed so before); twice that leaves the easing nothing to see.
  // The sweep comes down from 26 degrees: its cue lies toward the near side, over open felt in
  // this view (from below 0 it would lie under the Match pane).
  constexpr double kFrom = 26 * kDeg, kTo = 3 * kDeg, kSettled = 1.0;
  auto settledCapture = [&]() -> std::optional<nlohmann::json> {
    std::optional<double> final_since;
    for (const auto& d : windowLines("drawn")) {
      if (!d.contains("live_aim") || std::abs(d["live_aim"]["yaw"].get<double>() - kTo) > 1e-12)
        continue;
      if (!final_since) final_since = d["now"].get<double>();
      if (d["now"].get<double>() - *final_since >= kSettled && d.contains("capture")) return d;
    }
    return std::nullopt;
  };
  // The sweep's start, held until the window draws it in a captured frame (a loaded machine may
  // take a while to show the first aims: the sweep itself must not run past a window not yet
  // drawing them; the capture is where the pixels show the cue there, below).
  const auto startCapture = [&]() -> std::optional<nlohmann::json> {
    for (const auto& d : windowLines("drawn")) {
      if (d.contains("cue_stick") && d["cue_stick"]["source"] == "remote" &&
          d.contains("capture") && std::abs(drawnYaw(d["cue_stick"]) - kFrom) < 0.5 * kDeg) {
        return d;
      }
    }
    return std::nullopt;
  };
  for (const auto until = std::chrono::steady_clock::now() + 20s;
       !startCapture() && std::chrono::steady_clock::now() < until;) {
    ASSERT_TRUE(shooter.sendAim(aimAt(kFrom, 0.0, false)));
    pump([] { return false; }, 100ms);
  }
  const auto at_start = startCapture();
  ASSERT_TRUE(at_start) << "the window never drew the sweep's start in a captured frame\n"
                        << windowErr();
  // Aim: 1.2 s sweeping from 26 to 3 degrees at 30 Hz, then still (keep-alives) for at least
  // 1.5 s and until the window captured a settled frame (at most 20 s).
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t > 2.7 && (t > 20.0 || settledCapture())) break;
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
  EXPECT_GT(highest, kFrom - 5 * kDeg) << "the sweep's start was drawn";
  EXPECT_LT(lowest, kTo + 1 * kDeg) << "the sweep's end was drawn";

  // Once the shooter stopped, in the pixels of a frame captured kSettled s after the window first
  // had the final aim: the cue's maple lies along the line the test aimed, behind the cue ball
  // (the break's, where the server placed it), at the yaw and elevation it sent, projected
  // through the frame's reported camera (checked not mirrored); and not along the line the sweep
  // started from. The stretch from 4 cm (past the tip and ferrule) to 40 cm behind the centre:
  // near the tip, where the drawing's extra lift over the rail (it pivots about the tip: half a
  // degree here, 3.5 mm at 40 cm, about a pixel in this view) moves the shaft least; 1.5 px
  // either side of the projected axis, and the shaft's own half-width (over 6 mm, about 2 px)
  // beyond it, hold that and the settled aim's last 1 degree (7 mm at 40 cm).
  // Over 0.8 of the points show maple on the aimed line (a ball or the rail's shadow may cover
  // a few); under 0.1 on the starting line, 23 degrees away (at 4 cm already 1.6 cm, over a
  // shaft's width, apart), and that line in view: over half its points show the felt (not a
  // pane over it, where no cue could be seen).
  const auto settled = settledCapture();
  ASSERT_TRUE(settled) << "no frame captured with the settled aim: " << windowErr();
  const ReportedCamera camera = cameraOf(*settled);
  ASSERT_EQ(camera.mirrored(), "");
  const Image image = loadPng((*settled)["capture"].get<std::string>());
  ASSERT_EQ(image.width, camera.width);
  ASSERT_EQ(image.height, camera.height);
  const auto spec = table::loadTableSpec("wpa-9ft");
  ASSERT_TRUE(spec) << spec.error();
  const glm::dvec3 centre(cue_ball.x(), cue_ball.y(), spec->params.ball_radius);
  int seen = 0;
  const double aimed = mapleShare(image, camera, centre, kTo, 2 * kDeg, 0.04, 0.40, &seen);
  EXPECT_GE(seen, 10) << "the cue's line should cross the view";
  EXPECT_GT(aimed, 0.8) << "the cue not drawn along the shooter's aim: "
                        << (*settled)["capture"].get<std::string>();
  EXPECT_LT(mapleShare(image, camera, centre, kFrom, 2 * kDeg, 0.04, 0.40), 0.1)
      << "the cue still drawn along the sweep's start";
  EXPECT_GT(mapleShare(image, camera, centre, kFrom, 2 * kDeg, 0.04, 0.40, nullptr, isFelt), 0.5)
      << "the sweep's starting line is not in view (under a pane?): its check would be empty";

  // It moved, in the pixels: the frame captured while the window drew the sweep's start shows the
  // maple along the starting line and not along the aim it settled on (the same bounds).
  const ReportedCamera start_camera = cameraOf(*at_start);
  ASSERT_EQ(start_camera.mirrored(), "");
  const Image start_image = loadPng((*at_start)["capture"].get<std::string>());
  ASSERT_EQ(start_image.width, start_camera.width);
  EXPECT_GT(mapleShare(start_image, start_camera, centre, kFrom, 2 * kDeg, 0.04, 0.40), 0.8)
      << "the cue not drawn along the sweep's start: " << (*at_start)["capture"].get<std::string>();
  EXPECT_LT(mapleShare(start_image, start_camera, centre, kTo, 2 * kDeg, 0.04, 0.40), 0.1)
      << "the cue already drawn along the settled aim at the sweep's start";

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
