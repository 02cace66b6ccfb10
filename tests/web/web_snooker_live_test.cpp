// The web page follows a live snooker frame: a server playing snooker, two bots and pool-web; the
// page in headless Chromium shows the snooker table and, at rest, every ball where the server's
// latest state puts it, reds and colours alike (ids to 21).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "support/chromium_page.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/match_recorder.h"
#include "support/web_process.h"

namespace pool::client::test {
namespace {

// What the page's drawn balls (poolTest.status().drawn) get wrong about `view`: a ball on the table
// not drawn there, or more than 0.1 mm from where the server put it, or a potted ball drawn on the
// cloth; the black not on the table (it stays until the frame's end); empty when nothing.
std::string drawnDifference(const MatchView& view, const nlohmann::json& shown) {
  std::map<int, nlohmann::json> drawn;
  for (const auto& b : shown["drawn"]) drawn[b["id"].get<int>()] = b;
  if (view.balls.size() != 22u) return std::to_string(view.balls.size()) + " balls in the state";
  int on_table = 0;
  for (const auto& ball : view.balls) {
    const std::string name = "ball " + std::to_string(ball.id);
    const bool listed = drawn.count(ball.id) > 0;
    if (!physics::onTable(ball.state)) {
      if (listed && drawn[ball.id]["on"].get<bool>()) return name + " potted but drawn";
      continue;
    }
    ++on_table;
    if (!listed || !drawn[ball.id]["on"].get<bool>()) return name + " not drawn";
    const auto& d = drawn[ball.id];
    if (std::hypot(d["x"].get<double>() - ball.pos.x(), d["y"].get<double>() - ball.pos.y()) >
        1e-4) {
      return name + " drawn away from where the server put it";
    }
  }
  if (on_table < 2) return "fewer than two balls on the table";
  if (!drawn.count(21) || !drawn[21]["on"].get<bool>()) return "the black (21) not drawn";
  return "";
}

class WebSnookerLiveTest : public ClientIntegrationTest {};

TEST_F(WebSnookerLiveTest, ThePageFollowsAFrameWithEveryBallWhereTheServerPutsIt) {
  if (chromiumPath().empty()) POOL_NO_DISPLAY("no chromium (Debian's chromium package)");
  open(kWebSnookerLive, "web-snooker-live");
  MatchRecorder recorder(kWebSnookerLive);
  startServer({"--game", "snooker", "--rack-seed", "11"});
  // Bots that think between strokes leave the table at rest long enough to compare.
  startBot("alice", 3, {"--think", "3", "--level", "club"});
  startBot("bob", 4, {"--think", "3", "--level", "club"});
  ChildProcess& web = start("pool-web", webArgs(domain_), "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();
  ASSERT_TRUE(recorder.pump(40s,
                            [&] {
                              const MatchView* v = recorder.latest(recorder.firstMatch());
                              return v && inPlay(v->phase) && v->shot_number >= 2;
                            }))
      << "no snooker frame past its break-off\n"
      << logs();
  const std::string match = recorder.firstMatch();

  ChromiumPage page(file("chromium"), 1100, 700);
  ASSERT_TRUE(page.started());
  ASSERT_TRUE(page.open("http://127.0.0.1:" + std::to_string(port) + "/?match=" + match, 20s))
      << page.lastError();
  // The page at rest on the server's latest state, every ball compared. The page draws a state a
  // frame after it receives it, so a look between the two is looked at again (until a deadline:
  // a page that never draws the state fails with the last difference found).
  std::string difference = "the page never showed the latest state at rest";
  nlohmann::json shown;
  const auto deadline = std::chrono::steady_clock::now() + 90s;
  while (!difference.empty() && std::chrono::steady_clock::now() < deadline) {
    recorder.pump(100ms);
    const MatchView* v = recorder.latest(match);
    const auto status = page.evaluate("window.poolTest && window.poolTest.status()", 10s);
    if (!v || !status || status->is_null()) continue;
    if ((*status)["revision"] != v->revision || (*status)["inMotion"] != false) continue;
    shown = *status;
    difference = drawnDifference(*v, shown);
  }
  EXPECT_EQ(difference, "") << shown.dump() << "\n" << page.lastError() << logs();
  EXPECT_EQ(shown["table"], "snooker-12ft");

  // The page's lobby line for the match names both bots with their ratings and says how far the
  // frame has gone (the frame, its score and the shots), as the server's own lobby entry says.
  std::string line, wanted;
  const auto lobby_deadline = std::chrono::steady_clock::now() + 20s;
  while (std::chrono::steady_clock::now() < lobby_deadline) {
    recorder.pump(100ms);
    const LobbyEntry* e = recorder.client().lobby().find(match);
    const auto status = page.evaluate("window.poolTest.status()", 10s);
    if (!e || !status || status->is_null()) continue;
    for (const auto& l : (*status)["lobbyLines"]) {
      if (l["match"] == match) line = l["text"];
    }
    wanted = "";
    for (std::size_t s = 0; s < 2; ++s) {
      const std::string player = e->players[s] + " (" + std::to_string(e->ratings[s]) + ")";
      if (e->ratings[s] <= 0 || line.find(player) == std::string::npos) wanted += player + "; ";
    }
    for (const std::string& part :
         {"frame " + std::to_string(e->rack) + " " + std::to_string(e->rack_points[0]) + "-" +
              std::to_string(e->rack_points[1]),
          "shot " + std::to_string(e->shot_number)}) {
      if (line.find(part) == std::string::npos) wanted += part + "; ";
    }
    if (wanted.empty()) break;
  }
  EXPECT_EQ(wanted, "") << "the lobby line: " << line;

  // The page's player pages: each bot's snooker record with the strokes the server has counted
  // (as a client of the domain receives the same record).
  std::string missing = "no record";
  nlohmann::json players;
  const auto players_deadline = std::chrono::steady_clock::now() + 20s;
  while (!missing.empty() && std::chrono::steady_clock::now() < players_deadline) {
    recorder.pump(100ms);
    const auto status = page.evaluate("window.poolTest.status()", 10s);
    if (!status || status->is_null()) continue;
    players = (*status)["players"];
    missing.clear();
    for (const std::string name : {"alice", "bob"}) {
      const auto records = recorder.client().players().named(name);
      if (records.empty()) {
        missing += name + " (no record received); ";
        continue;
      }
      const int n = records.front()->strokes;
      const std::string strokes = std::to_string(n) + (n == 1 ? " stroke" : " strokes") + " in all";
      bool found = false;
      for (const auto& p : players) {
        if (p["text"].get<std::string>().rfind(name + " at ", 0) != 0) continue;
        for (const auto& l : p["lines"]) {
          found = found || l.get<std::string>().find(strokes) != std::string::npos;
        }
      }
      if (!found) missing += name + ": " + strokes + "; ";
    }
  }
  EXPECT_EQ(missing, "") << players.dump();
}

}  // namespace
}  // namespace pool::client::test
