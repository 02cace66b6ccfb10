// The lobby's words for one match: its players with their ratings, and how far it has gone.
#pragma once

#include <string>

#include "client/net/match_types.h"

namespace pool::app {

/// The players with their ratings in the table's game: "Ada (1562) vs Bo (1438)"; a free seat
/// "-", an unrated one (a rating of 0: unsigned) by its name alone.
std::string lobbyPlayers(const client::LobbyEntry& entry);

/// How far a match has gone: the race's score, the rack in play with its points where the game
/// keeps them, and the shots played: "racks 2-1, rack 4, shot 37", "frames 1-0, frame 2 45-12,
/// shot 37", "games 0-0, game 1 4-3, shot 18"; a practice table "practice, shot 12"; "" before
/// the first rack.
std::string lobbyProgress(const client::LobbyEntry& entry);

}  // namespace pool::app
