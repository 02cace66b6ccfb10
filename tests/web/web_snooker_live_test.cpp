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
  // The page at rest on the server's latest state: compare every ball.
  nlohmann::json shown;
  MatchView latest;
  const auto deadline = std::chrono::steady_clock::now() + 90s;
  while (std::chrono::steady_clock::now() < deadline) {
    recorder.pump(100ms);
    const MatchView* v = recorder.latest(match);
    const auto status = page.evaluate("window.poolTest && window.poolTest.status()", 10s);
    if (!v || !status || status->is_null()) continue;
    if ((*status)["revision"] != v->revision || (*status)["inMotion"] != false) continue;
    shown = *status;
    latest = *v;
    break;
  }
  ASSERT_FALSE(shown.is_null()) << "the page never showed the latest state at rest\n"
                                << page.lastError() << logs();
  EXPECT_EQ(shown["table"], "snooker-12ft") << shown.dump();
  std::map<int, nlohmann::json> drawn;
  for (const auto& b : shown["drawn"]) drawn[b["id"].get<int>()] = b;
  ASSERT_EQ(latest.balls.size(), 22u);
  int on_table = 0;
  for (const auto& ball : latest.balls) {
    const bool listed = drawn.count(ball.id) > 0;
    if (!physics::onTable(ball.state)) {
      // Potted (or in hand): not drawn on the cloth.
      EXPECT_TRUE(!listed || !drawn[ball.id]["on"].get<bool>()) << "ball " << ball.id;
      continue;
    }
    ++on_table;
    ASSERT_TRUE(listed) << "ball " << ball.id << " not drawn";
    const auto& d = drawn[ball.id];
    EXPECT_TRUE(d["on"].get<bool>()) << "ball " << ball.id;
    // Where the server put it, to a tenth of a millimetre (the page draws the published state).
    EXPECT_NEAR(d["x"].get<double>(), ball.pos.x(), 1e-4) << "ball " << ball.id;
    EXPECT_NEAR(d["y"].get<double>(), ball.pos.y(), 1e-4) << "ball " << ball.id;
  }
  EXPECT_GE(on_table, 2);
  // The black (id 21) is on the table until the frame's end.
  EXPECT_TRUE(drawn.count(21) && drawn[21]["on"].get<bool>()) << shown.dump();
}

}  // namespace
}  // namespace pool::client::test
