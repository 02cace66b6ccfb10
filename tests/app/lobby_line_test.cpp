// The lobby's words for a match: ratings beside the players, the race's score, the rack in play
// (with a frame's or a game's points) and the shot count, in each game's own words.
#include "client/app/lobby_line.h"

#include <gtest/gtest.h>

namespace pool::app {
namespace {

client::LobbyEntry entryOf(rules::Game game) {
  client::LobbyEntry e;
  e.match = "srv-1";
  e.settings.game = game;
  e.players = {"Ada", "Bo"};
  e.ratings = {1562, 1438};
  e.phase = client::MatchPhase::Open;
  e.racks_won = {2, 1};
  e.rack = 4;
  e.shot_number = 37;
  e.rack_points = {45, 12};
  return e;
}

TEST(LobbyLine, PlayersCarryTheirRatingsAndAFreeSeatIsADash) {
  client::LobbyEntry e = entryOf(rules::Game::EightBall);
  EXPECT_EQ(lobbyPlayers(e), "Ada (1562) vs Bo (1438)");
  e.players[1].clear();
  e.ratings[1] = 0;
  EXPECT_EQ(lobbyPlayers(e), "Ada (1562) vs -");
  e.ratings[0] = 0;  // an unsigned seat is not rated
  EXPECT_EQ(lobbyPlayers(e), "Ada vs -");
}

TEST(LobbyLine, ProgressInEachGamesWords) {
  // A pool game keeps no points within a rack: the race's score, the rack and the shots.
  EXPECT_EQ(lobbyProgress(entryOf(rules::Game::NineBall)), "racks 2-1, rack 4, shot 37");
  EXPECT_EQ(lobbyProgress(entryOf(rules::Game::Snooker)), "frames 2-1, frame 4 45-12, shot 37");
  EXPECT_EQ(lobbyProgress(entryOf(rules::Game::ThreeCushion)), "games 2-1, game 4 45-12, shot 37");
  client::LobbyEntry waiting = entryOf(rules::Game::EightBall);
  waiting.rack = 0;
  EXPECT_EQ(lobbyProgress(waiting), "");
  client::LobbyEntry practice = entryOf(rules::Game::Snooker);
  practice.settings.practice = true;
  EXPECT_EQ(lobbyProgress(practice), "practice, shot 37");
}

}  // namespace
}  // namespace pool::app
