// The client's lobby keeps its bounds: a flood under one server id or many stays within them.
#include "client/net/lobby.h"

#include <gtest/gtest.h>

namespace pool::client {
namespace {

LobbyEntry entry(const std::string& server, int number) {
  LobbyEntry e;
  e.server = server;
  e.match = server + "-" + std::to_string(number);
  e.table = "wpa-9ft";
  e.phase = MatchPhase::Lobby;
  return e;
}

std::size_t held(const Lobby& lobby, const std::string& server) {
  const auto it = lobby.servers().find(server);
  return it == lobby.servers().end() ? 0 : it->second.matches.size();
}

TEST(LobbyTest, TwentyThousandEntriesUnderANewServerIdKeepOnlyItsShare) {
  Lobby lobby;
  LobbyEntry full = entry("srv", 1);
  full.seats_taken = 2;
  lobby.update(full);
  LobbyEntry playing = entry("srv", 2);
  playing.phase = MatchPhase::Break;
  playing.seats_taken = 2;
  lobby.update(playing);
  for (int i = 1; i <= 20000; ++i) lobby.update(entry("flood", i));
  EXPECT_EQ(lobby.size(), 2u + LobbyBounds{}.per_server);
  EXPECT_EQ(held(lobby, "flood"), LobbyBounds{}.per_server);
  EXPECT_EQ(lobby.refused(), 20000u - LobbyBounds{}.per_server);
  EXPECT_NE(lobby.find("flood-256"), nullptr);
  EXPECT_EQ(lobby.find("flood-257"), nullptr);
  EXPECT_EQ(lobby.entries().size(), lobby.size());
  ASSERT_NE(lobby.find("srv-1"), nullptr);
  EXPECT_EQ(lobby.firstInPlay(), "srv-2");
  EXPECT_EQ(lobby.lowestWithFreeSeat(), "flood-1");
  // 2 000 new ids of two entries each fill the lobby to its total: the flooding id gives way,
  // srv keeps its two.
  for (int id = 0; id < 2000; ++id) {
    for (int i = 1; i <= 2; ++i) lobby.update(entry("made-up" + std::to_string(id), i));
  }
  EXPECT_EQ(lobby.size(), LobbyBounds{}.kept);
  EXPECT_EQ(held(lobby, "srv"), 2u);
  EXPECT_EQ(held(lobby, "made-up1999"), 2u);
  EXPECT_LT(held(lobby, "flood"), 100u);
  EXPECT_NE(lobby.find("flood-1"), nullptr) << "the lowest-numbered go last";
  // Updates of kept matches and removals still pass.
  playing.phase = MatchPhase::Over;
  EXPECT_TRUE(lobby.update(playing).kept);
  EXPECT_EQ(lobby.find("srv-2")->phase, MatchPhase::Over);
  lobby.remove("srv-1");
  EXPECT_EQ(lobby.find("srv-1"), nullptr);
}

TEST(LobbyTest, TheLargestIdGivesWayHighestNumberedFirstOfTwoTheOneSeenLater) {
  Lobby lobby(LobbyBounds{4, 6});
  for (int i = 1; i <= 3; ++i) EXPECT_TRUE(lobby.update(entry("a", i)).kept);
  for (int i = 1; i <= 3; ++i) EXPECT_TRUE(lobby.update(entry("b", i)).kept);
  EXPECT_EQ(lobby.size(), 6u);
  // a and b hold three each: b, seen later, gives up its highest-numbered.
  const LobbyUpdate first = lobby.update(entry("c", 1));
  EXPECT_TRUE(first.kept);
  EXPECT_EQ(first.gave_way, "b-3");
  EXPECT_EQ(lobby.update(entry("c", 2)).gave_way, "a-3");
  // Now every id holds two: none holds two more than c's two.
  EXPECT_FALSE(lobby.update(entry("c", 3)).kept);
  EXPECT_EQ(lobby.refused(), 1u);
  EXPECT_EQ(lobby.size(), 6u);
  // Past its own share an id is refused even with room to spare.
  lobby.remove("a-1");
  lobby.remove("a-2");
  EXPECT_TRUE(lobby.update(entry("c", 3)).kept);
  EXPECT_TRUE(lobby.update(entry("c", 4)).kept);
  EXPECT_FALSE(lobby.update(entry("c", 5)).kept);
  // A match that moves to another server id counts there.
  LobbyEntry moved = entry("b", 1);
  moved.server = "d";
  EXPECT_TRUE(lobby.update(moved).kept);
  EXPECT_EQ(held(lobby, "b"), 1u);
  EXPECT_EQ(held(lobby, "d"), 1u);
  EXPECT_EQ(lobby.find("b-1")->server, "d");
}

}  // namespace
}  // namespace pool::client
