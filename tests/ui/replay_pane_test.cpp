// The stored shot's replay pane says which shot is asked, then which is shown with its players,
// game and table above its buttons; a problem and an export's outcome below them.
#include "client/ui/replay_pane.h"

#include <gtest/gtest.h>

namespace pool::ui {
namespace {

using Lines = std::vector<std::string>;

protocol::HistoryShot paneShot(std::uint32_t request, std::uint32_t n) {
  protocol::HistoryShot s;
  s.request = request;
  s.match = "srv-4";
  s.found = true;
  s.shot_number = n;
  s.shots = 7;
  s.game = rules::Game::NineBall;
  s.table = "wpa-9ft";
  s.players = {"Ada", ""};
  s.seat = 0;
  s.verdict_text = "foul (cue_ball_scratch); seat 1 to shoot";
  return s;
}

TEST(ReplayPane, SaysTheShotAskedThenTheShotShownAndKeepsProblemsBelowTheButtons) {
  app::StoredReplay r;
  r.open("srv-4");
  auto lines = replayPaneLines(r, "");
  EXPECT_EQ(lines.above, Lines{"asking the server of srv-4 for shot 1..."});
  EXPECT_TRUE(lines.below.empty());

  r.open("srv-4", 5);
  r.due(0.0);
  r.asked(1, 0.0);
  ASSERT_TRUE(r.take(paneShot(1, 5), 0.0));
  lines = replayPaneLines(r, "exported to /tmp/srv-4-shot-5.json (pool-sim srv-4-shot-5.json)");
  EXPECT_EQ(lines.above, (Lines{"Replay of srv-4, shot 5 of 7: Ada - foul (cue ball scratch); "
                                "Player 2 to shoot",
                                "Ada v Player 2, 9-ball on wpa-9ft"}));
  EXPECT_EQ(lines.below, Lines{"exported to /tmp/srv-4-shot-5.json (pool-sim srv-4-shot-5.json)"});
  EXPECT_EQ(lines.all().size(), 3u);

  // The next shot asked: still shown until it comes; then the server's refusal below.
  ASSERT_TRUE(r.next());
  r.due(1.0);
  r.asked(2, 1.0);
  lines = replayPaneLines(r, "");
  ASSERT_EQ(lines.above.size(), 3u);
  EXPECT_EQ(lines.above[2], "asking the server of srv-4 for shot 6...");
  protocol::HistoryShot refused;
  refused.request = 2;
  refused.match = "srv-4";
  refused.shots = 7;
  refused.error = "shot 6 of srv-4 is still being played";
  ASSERT_TRUE(r.take(refused, 1.1));
  lines = replayPaneLines(r, "");
  EXPECT_EQ(lines.above.size(), 2u);
  EXPECT_EQ(lines.below, Lines{"shot 6 of srv-4 is still being played"});
}

}  // namespace
}  // namespace pool::ui
