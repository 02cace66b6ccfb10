// The gateway's bounded lobby: entries kept per server id and in all, a new id taking room only
// from one holding more, and the lobby message cut to its bytes, the largest ids first.
#include "client/web/bounded_lobby.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace pool::web {
namespace {

client::LobbyEntry entry(const std::string& server, int number) {
  client::LobbyEntry e;
  e.server = server;
  e.match = server + "-" + std::to_string(number);
  e.table = "wpa-9ft";
  e.phase = protocol::MatchPhase::Open;
  return e;
}

/// Entries per server id in a lobby message.
std::map<std::string, int> perServer(const std::string& message) {
  std::map<std::string, int> out;
  const auto json = nlohmann::json::parse(message);
  for (const auto& e : json["matches"]) {
    ++out[e["server"].get<std::string>()];
  }
  return out;
}

TEST(BoundedLobbyTest, AFloodingIdCrowdsOutOnlyItselfAndKnownIdsKeepTheirEntries) {
  LobbyLimits limits;
  limits.per_server = 8;
  limits.kept = 32;
  BoundedLobby lobby(limits);
  ASSERT_TRUE(lobby.update(entry("srv", 1)));
  ASSERT_TRUE(lobby.update(entry("srv", 2)));
  // One id past its share: the rest of its entries are refused.
  for (int i = 1; i <= 100; ++i) lobby.update(entry("flood", i));
  EXPECT_EQ(perServer(lobby.message())["flood"], 8);
  EXPECT_NE(lobby.find("flood-8"), nullptr);
  EXPECT_EQ(lobby.find("flood-9"), nullptr);
  // An update of a kept match always passes.
  client::LobbyEntry changed = entry("flood", 3);
  changed.name = "renamed";
  EXPECT_TRUE(lobby.update(changed));
  EXPECT_EQ(lobby.find("flood-3")->name, "renamed");

  // Many ids fill the lobby: two entries each.
  for (int id = 0; id < 20; ++id) {
    for (int i = 1; i <= 2; ++i) lobby.update(entry("made-up" + std::to_string(id), i));
  }
  EXPECT_EQ(lobby.size(), 32u);
  // flood (the largest) gave up its highest-numbered entries to them; srv kept both of its.
  const auto shares = perServer(lobby.message());
  EXPECT_EQ(shares.at("srv"), 2);
  EXPECT_LE(shares.at("flood"), 3);
  EXPECT_NE(lobby.find("flood-1"), nullptr) << "the lowest-numbered go last";
  // Now every id holds two at most: a new id takes one entry from an id holding two, never an
  // entry of an id holding as few as it would.
  EXPECT_TRUE(lobby.update(entry("late", 1)));
  EXPECT_FALSE(lobby.update(entry("late", 2))) << "no id holds two more than late's one";
  EXPECT_EQ(perServer(lobby.message()).at("srv"), 2);
  EXPECT_EQ(lobby.size(), 32u);
}

TEST(BoundedLobbyTest, TheMessageIsCutToItsBytesLargestIdFirst) {
  LobbyLimits limits;
  limits.served_bytes = 6000;
  BoundedLobby lobby(limits);
  lobby.update(entry("srv", 1));
  lobby.update(entry("den", 1));
  lobby.update(entry("den", 2));
  for (int i = 1; i <= 200; ++i) lobby.update(entry("flood", i));
  const std::string message = lobby.message();
  EXPECT_LE(message.size(), 6000u);
  const auto shares = perServer(message);
  EXPECT_EQ(shares.at("srv"), 1);
  EXPECT_EQ(shares.at("den"), 2);
  EXPECT_GT(shares.at("flood"), 0);
  EXPECT_LT(shares.at("flood"), 200);
  // Lowest-numbered first, as the page lists them.
  const auto matches = nlohmann::json::parse(message)["matches"];
  EXPECT_EQ(matches[0]["match"], "den-1");
}

}  // namespace
}  // namespace pool::web
