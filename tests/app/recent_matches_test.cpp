// The lobby's history: a match seen played and then gone from the lobby is listed, newest first,
// at most RecentMatches::kKept; one never played, or still listed, is not.
#include "client/app/recent_matches.h"

#include <gtest/gtest.h>

namespace pool::app {
namespace {

client::LobbyEntry entry(const std::string& match, std::uint32_t shots) {
  client::LobbyEntry e;
  e.match = match;
  e.server = "srv";
  e.table = "wpa-9ft";
  e.shot_number = shots;
  return e;
}

TEST(RecentMatches, AMatchPlayedThenGoneIsListedWithItsLastShotCount) {
  client::Lobby lobby;
  RecentMatches recent;
  lobby.update(entry("srv-1", 3));
  lobby.update(entry("srv-2", 0));
  recent.see(lobby);
  EXPECT_TRUE(recent.gone().empty()) << "both are still listed";
  auto played = entry("srv-1", 8);
  played.players = {"ann", "bob"};
  lobby.update(played);
  recent.see(lobby);
  played.players[0].clear();  // ann left after the last shot
  played.shot_number = 9;
  lobby.update(played);
  recent.see(lobby);
  lobby.remove("srv-1");
  lobby.remove("srv-2");
  recent.see(lobby);
  const auto gone = recent.gone();
  ASSERT_EQ(gone.size(), 1u) << "srv-2 never had a shot";
  EXPECT_EQ(gone[0]->match, "srv-1");
  EXPECT_EQ(gone[0]->shot_number, 9u) << "as the lobby last showed it";
  EXPECT_EQ(gone[0]->players[0], "ann") << "who played it, though she left";
  EXPECT_EQ(gone[0]->players[1], "bob");
}

TEST(RecentMatches, TheNewestComeFirstAndTheOldestGiveWay) {
  client::Lobby lobby;
  RecentMatches recent;
  const int n = static_cast<int>(RecentMatches::kKept) + 2;
  for (int i = 1; i <= n; ++i) {
    lobby.update(entry("srv-" + std::to_string(i), 1));
    recent.see(lobby);
    lobby.remove("srv-" + std::to_string(i));
    recent.see(lobby);
  }
  const auto gone = recent.gone();
  ASSERT_EQ(gone.size(), RecentMatches::kKept);
  EXPECT_EQ(gone.front()->match, "srv-" + std::to_string(n));
  EXPECT_EQ(gone.back()->match, "srv-3") << "srv-1 and srv-2 gave way";
}

}  // namespace
}  // namespace pool::app
