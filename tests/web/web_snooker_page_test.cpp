// The page draws a snooker table in headless Chromium: the gateway's own table and state messages.
// No snooker match runs on the wire: the page is handed the messages pool-web would send
// (web_json's tableJson and stateJson), and its screenshot must show each ball in its snooker
// colour and the baulk line lighter than the felt beside it, at points the test projects itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "client/web/web_json.h"
#include "support/chromium_page.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/web_process.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

using nlohmann::json;

enum class Hue { White, Black, Red, Pink, Yellow, Other };

/// A ball's pixel as the page shows it (sRGB: the deep red's green and blue lifted a little).
Hue hueOf(const Rgb& p) {
  const double r = p[0], g = p[1], b = p[2];
  const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
  if (hi < 75) return Hue::Black;
  if (lo > 150 && hi - lo < 40) return Hue::White;
  if (r < 90 || r < hi) return Hue::Other;
  if (g < 0.35 * r && b < 0.35 * r) return Hue::Red;
  if (g > 0.6 * r && b < 0.4 * r) return Hue::Yellow;
  if (g > 0.45 * r && b > g && b < 0.95 * r) return Hue::Pink;
  return Hue::Other;
}

struct Placed {
  int id;
  double x, y;
  Hue hue;
};

using WebSnookerPageTest = ClientIntegrationTest;

/// Opens the page on `match` from pool-web at `port` and waits until it is connected and watching
/// it (the gateway knows no such match: nothing of it comes on the wire).
bool openWatching(ChromiumPage& page, std::uint16_t port, const std::string& match) {
  if (!page.started()) return false;
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/?match=" + match;
  if (!page.open(url, std::chrono::seconds(20))) return false;
  for (int i = 0; i < 100; ++i) {
    const auto s =
        page.evaluate("window.poolTest && window.poolTest.status()", std::chrono::seconds(5));
    if (s && s->is_object() && (*s)["connected"] == true && (*s)["match"] == match) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

TEST_F(WebSnookerPageTest, ThePageDrawsTheSnookerColoursAndTheBaulkLine) {
  if (chromiumPath().empty()) POOL_NO_DISPLAY("no chromium (Debian's chromium package)");
  open(kWebSnookerPage, "web-snooker-page");
  ChildProcess& web = start("pool-web", webArgs(domain_), "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();

  const auto spec = table::loadTableSpec("snooker-12ft");
  ASSERT_TRUE(spec) << spec.error();
  ASSERT_TRUE(spec->snooker_marks.has_value());
  const double r = spec->params.ball_radius;
  const double baulk_x = -spec->length / 2 + spec->snooker_marks->baulk_line;
  const std::vector<Placed> placed = {{0, -1.2, -0.15, Hue::White},
                                      {5, 0.3, 0.45, Hue::Red},
                                      {20, 1.0, -0.35, Hue::Pink},
                                      {21, 1.45, 0.3, Hue::Black},
                                      {16, -0.55, -0.5, Hue::Yellow}};
  protocol::MatchView view;
  view.match = "snooker-view";
  view.revision = 1;
  view.phase = protocol::MatchPhase::Open;
  view.seats[0].name = "ann";
  view.seats[1].name = "bea";
  view.shooter = 0;
  for (const Placed& p : placed) {
    physics::Ball ball;
    ball.id = p.id;
    ball.pos = Eigen::Vector3d(p.x, p.y, r);
    view.balls.push_back(ball);
  }
  const auto table = web::tableJson("snooker-12ft");
  ASSERT_TRUE(table) << table.error();

  ChromiumPage page(file("chromium"), 1100, 700);
  ASSERT_TRUE(openWatching(page, port, view.match)) << page.lastError() << logs();
  ASSERT_TRUE(page.setViewport(1100, 700, false, std::chrono::seconds(20))) << page.lastError();
  const std::string feed = "(() => { try { window.poolTest.receive(" + *table +
                           "); window.poolTest.receive(" + web::stateJson(view) +
                           "); return 'ok'; } catch (e) { return String(e); } })()";
  const auto fed = page.evaluate(feed, std::chrono::seconds(10));
  ASSERT_TRUE(fed) << page.lastError();
  ASSERT_EQ(*fed, "ok");
  int frames = -1;
  for (int i = 0; i < 100; ++i) {
    const auto s = page.evaluate("window.poolTest.status()", std::chrono::seconds(5));
    if (s && (*s)["table"] == "snooker-12ft" && (*s)["drawn"].size() == placed.size()) {
      if (frames < 0) frames = (*s)["frames"].get<int>();
      if ((*s)["frames"].get<int>() >= frames + 3) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string png = page.screenshot(std::chrono::seconds(20));
  ASSERT_FALSE(png.empty()) << page.lastError();
  const std::string path = file("web-snooker-page.png");
  std::ofstream(path, std::ios::binary) << png;
  const Image shot = loadPng(path);
  ASSERT_EQ(shot.width, 1100);

  const auto c = page.evaluate("window.poolTest.camera()", std::chrono::seconds(10));
  ASSERT_TRUE(c && c->is_object()) << page.lastError();
  ReportedCamera cam;
  cam.view = matrixOf((*c)["view"]);
  cam.projection = matrixOf((*c)["projection"]);
  ASSERT_EQ(cam.mirrored(), "");
  const auto& rect = (*c)["rect"];
  const auto project = [&](double x, double y, double z) {
    const glm::dvec4 clip =
        glm::dmat4(cam.projection) * glm::dmat4(cam.view) * glm::dvec4(x, y, z, 1.0);
    return std::array<double, 2>{
        rect[0].get<double>() + (clip.x / clip.w + 1.0) / 2.0 * rect[2].get<double>(),
        rect[1].get<double>() + (1.0 - clip.y / clip.w) / 2.0 * rect[3].get<double>()};
  };
  const auto at = [&](const std::array<double, 2>& p, int dx, int dy) -> const Rgb& {
    return shot.at(static_cast<int>(p[0]) + dx, static_cast<int>(p[1]) + dy);
  };

  // Each ball at its top: most of the 5 × 5 pixels there in its hue class.
  for (const Placed& b : placed) {
    const auto px = project(b.x, b.y, 2 * r);
    int hits = 0;
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) hits += hueOf(at(px, dx, dy)) == b.hue ? 1 : 0;
    }
    EXPECT_GE(hits, 13) << "ball " << b.id << " at (" << px[0] << ", " << px[1] << ")";
  }

  // The baulk line, clear of the D and the balls: its brightest pixel across it lighter than
  // the felt 15 mm either side.
  const auto peak = [&](double x, double y) {
    const auto px = project(x, y, 0.0);
    double best = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) best = std::max(best, luminance(at(px, dx, dy)));
    }
    return best;
  };
  for (const double y : {-0.6, 0.6}) {
    const double line = peak(baulk_x, y);
    for (const double side : {-0.015, 0.015}) {
      EXPECT_GT(line, 1.08 * peak(baulk_x + side, y))
          << "baulk line at y " << y << " against the felt " << side << " m off";
    }
    // No line at its mirror on the other half.
    EXPECT_LT(peak(-baulk_x, y), 1.05 * peak(-baulk_x + 0.015, y)) << y;
  }
  // The blue spot at the centre.
  EXPECT_GT(peak(0.0, 0.0), 1.08 * peak(0.02, 0.0)) << "blue spot";
}

// The page's snooker scoreboard: a frame's state message (web_json's stateJson of the match
// view) shows the frame score, the frames won and the race in frames, the break and each
// player's highest, the ball on, the reds left and the points remaining, and the snookers one
// player needs (Section 1: on a colour after a red, 2 reds left and all six colours: 7 + 2 × 8 +
// 27 = 50 on the table; bea 55 ahead of ann: ann 5 short).
TEST_F(WebSnookerPageTest, TheScoreboardShowsTheFrameTheBreakAndTheBallOn) {
  if (chromiumPath().empty()) POOL_NO_DISPLAY("no chromium (Debian's chromium package)");
  open(kWebSnookerScore, "web-snooker-score");
  ChildProcess& web = start("pool-web", webArgs(domain_), "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();
  const auto spec = table::loadTableSpec("snooker-12ft");
  ASSERT_TRUE(spec) << spec.error();
  const double r = spec->params.ball_radius;

  protocol::MatchView view;
  view.match = "snooker-score";
  view.revision = 7;
  view.phase = protocol::MatchPhase::Open;
  view.rack = 2;
  view.settings.game = rules::Game::Snooker;
  view.settings.race_to = 3;
  view.seats[0].name = "ann";
  view.seats[1].name = "bea";
  view.seats[0].points = 8;
  view.seats[1].points = 63;
  view.seats[0].high_run = 8;
  view.seats[1].high_run = 41;
  view.seats[0].racks_won = 1;
  view.shooter = 1;
  view.run = 17;
  view.ball_on = rules::kOnColour;
  const auto put = [&](int id, double x, double y) {
    physics::Ball ball;
    ball.id = id;
    ball.pos = Eigen::Vector3d(x, y, r);
    view.balls.push_back(ball);
  };
  put(0, 0.5, 0.2);
  put(3, 0.9, 0.1);
  put(9, 1.1, -0.2);
  for (int id = 16; id <= 21; ++id) put(id, -1.0 + 0.3 * (id - 16), -0.5);
  const auto table = web::tableJson("snooker-12ft");
  ASSERT_TRUE(table) << table.error();

  ChromiumPage page(file("chromium"), 1100, 700);
  ASSERT_TRUE(openWatching(page, port, view.match)) << page.lastError() << logs();
  const std::string feed = "(() => { try { window.poolTest.receive(" + *table +
                           "); window.poolTest.receive(" + web::stateJson(view) +
                           "); return document.getElementById('facts').innerText; } catch (e) "
                           "{ return 'error: ' + String(e); } })()";
  const auto facts = page.evaluate(feed, std::chrono::seconds(10));
  ASSERT_TRUE(facts && facts->is_string()) << page.lastError();
  const std::string text = facts->get<std::string>();
  for (const char* said :
       {"Frame 2: ann 8, bea 63.", "Frames won: ann 1, bea 0", "(race to 3 frames)",
        "bea's break: 17.", "Highest breaks: ann 8, bea 41.", "bea to play, on a colour.",
        "2 reds left, 50 points remaining.", "ann needs snookers: 5 points short."}) {
    EXPECT_NE(text.find(said), std::string::npos) << "no \"" << said << "\" in:\n" << text;
  }
  EXPECT_EQ(text.find("Open table"), std::string::npos) << "no pool groups in snooker:\n" << text;
  // A free ball, in hand in the D.
  view.revision = 8;
  view.free_ball = true;
  view.ball_on = rules::kOnRed;
  view.run = 0;
  view.ball_in_hand = rules::BallInHand::InTheD;
  const auto again = page.evaluate("(() => { window.poolTest.receive(" + web::stateJson(view) +
                                       "); return document.getElementById('facts').innerText; })()",
                                   std::chrono::seconds(10));
  ASSERT_TRUE(again && again->is_string()) << page.lastError();
  EXPECT_NE(again->get<std::string>().find(
                "bea to play, free ball, on a red, with the cue ball in hand in the D."),
            std::string::npos)
      << again->get<std::string>();
}

}  // namespace
}  // namespace pool::client::test
