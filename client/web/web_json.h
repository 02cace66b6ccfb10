// The messages pool-web sends to browsers, as JSON text: the lobby, a table's drawing, match
// states, shot results and table frames.
#pragma once

#include <string>
#include <vector>

#include "client/net/lobby.h"
#include "client/net/match_types.h"
#include "core/result.h"
#include "protocol/player_stats.h"
#include "protocol/tournament_view.h"

namespace pool::web {

/// True for a table name the gateway may look up: 1–32 of [a-z0-9-], so a name a sample carries
/// can never reach outside assets/tables.
bool validTableName(const std::string& name);

/// One lobby entry: {match, server, name, table, phase, players, racks_won, race_to, settings,
/// spectators, in_play}.
std::string lobbyEntryJson(const client::LobbyEntry& entry);

/// Balls as the page draws them: [[id, x, y, z, qw, qx, qy, qz, on the table (1/0)], ...],
/// positions to 0.01 mm and orientations to 1e-5.
std::string ballsArray(const std::vector<physics::Ball>& balls);

/// {"type":"lobby","matches":[entries...]} of entries made by lobbyEntryJson, in their order.
std::string lobbyJson(const std::vector<const std::string*>& entries);

/// The players' records for the page's player pages: {"type":"players","players":[{server,
/// player (the key in hex), name, game, rating, rating_deviation, matches, matches_won, racks,
/// racks_won, strokes, attempts, pots, breaks, break_pots, break_and_runs, fouls, safeties,
/// high_run}, ...]}, at most `limit` of them in the order given.
std::string playersJson(const std::vector<const protocol::PlayerStats*>& players,
                        std::size_t limit);

/// The tournaments for the page's brackets: {"type":"tournaments","tournaments":[{tournament,
/// server, name, format, game, race_to, phase, capacity, entrants: [{name, rating, seed, place,
/// withdrawn}], matches: [{round, a, b, state (0 waiting, 1 ready, 2 in play, 3 decided), winner,
/// racks_a, racks_b, forfeit, match}], champion}, ...]} (entrants and matches by index; -1: none).
std::string tournamentsJson(const std::vector<const protocol::TournamentView*>& tournaments);

/// {"type":"table","name":...,"length","width","cushion_width","rail_width","nose_height",
/// "ball_radius","noses":[{a,b,normal}],"holes":[{name,centre,radius}],"lamps":{...},
/// "colours":{...}}: what the page needs to draw the table as the game does (its geometry from
/// the table spec, the game window's palette and lamps). Fails for an unknown or invalid name.
Result<std::string> tableJson(const std::string& table_name);

/// {"type":"state","match":...,"state":{the spectator's match_state line},"balls":[...],
/// "settings":"8-ball, race to 1, ...","verdict_words":the last verdict as the HUD says it,
/// "snooker":null, or in a snooker match {"ball_on":"on a red","free_ball","reds_left",
/// "points_remaining","snookers_required":[seat 0, seat 1]} (client/app/scoreboard.h)}.
std::string stateJson(const client::MatchView& view);

/// {"type":"result","match":...,"result":{the spectator's shot_result line},"verdict_words":...}.
std::string resultJson(const client::ShotReport& report);

/// {"type":"frame","match":...,"shot":n,"frame":k,"t":s,"balls":[[id,x,y,z,qw,qx,qy,qz,on]...]}
/// with positions to 0.01 mm and orientations to 1e-5.
std::string frameJson(const client::TableFrame& frame);

}  // namespace pool::web
