// The lobby screen (Dear ImGui): every open match of every server, to join, start or watch.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "client/net/lobby.h"
#include "client/net/player_book.h"
#include "protocol/match_settings.h"
#include "protocol/seat_request.h"
#include "protocol/tournament_view.h"

namespace pool::ui {

/// What the player picked in the lobby.
struct LobbyChoice {
  /// Play: a seat; PlayBot: a seat at the first free table and a bot of the options' level in
  /// the other; Spectate: watch; Cancel: stop waiting for a match to join; Replay: the match's
  /// stored shots, from its last; Enter: enter the tournament `match` names; AddBot: a bot of the
  /// options' level enters it; OpenTournament: open one of the options' game, race, format,
  /// entrants and handicap, and enter it.
  enum class Kind : std::uint8_t {
    Play,
    PlayBot,
    Spectate,
    Cancel,
    Replay,
    Enter,
    AddBot,
    OpenTournament
  } kind = Kind::Play;
  std::string match;  ///< empty: the first free table (Play) or the first match in play
                      ///< (Spectate); Enter, AddBot: the tournament
};

/// How a fresh table is to be played, as the lobby's options set it: game, race, breaks, shot
/// clock (0: off), or a practice table. Kept by the window between frames.
struct TableOptions {
  int game = 8;     ///< 8, 9, 10, 3 (three-cushion) or 22 (snooker): rules::gameOfNumber
  int race_to = 1;  ///< racks (snooker: frames; three-cushion: games)
  int points = protocol::kDefaultPoints;  ///< three-cushion: points that win a game
  bool winner_breaks = false;
  int shot_clock = 0;  ///< s; 0: off
  bool practice = false;
  int bot_level = 1;  ///< "Play the bot": 0 beginner, 1 club (pool-bot's default), 2 league, 3 pro
  int tournament_format = 0;  ///< a tournament to open: protocol::TournamentFormat's value
  int tournament_entrants = 4;
  bool handicap = false;

  /// As the match settings a seat request carries (checked by protocol::checkSettings); a
  /// practice table racks the game picked (without race or clock).
  protocol::MatchSettings settings() const;
  /// A tournament to open as the options say (its game and race are settings()'s).
  protocol::TournamentOpening opening() const;
};

/// Draws the lobby for this frame; `joining` greys the buttons while answers are pending. The
/// options of a fresh table are edited in `options`; "Practice" sets its `practice` and plays at a
/// new table, "New game" clears it.
/// Below the matches, the tournaments and their brackets (a match in play can be watched; one
/// taking entries entered, by this player (key `me`, hex) or a bot), a tournament to open, then
/// every player's rating and statistics per game (`players`), and the matches played here that
/// have left the lobby (`recent`, newest first), each with a Replay button.
std::optional<LobbyChoice> drawLobby(
    const client::Lobby& lobby, const std::map<std::string, protocol::TournamentView>& tournaments,
    const client::PlayerBook& players, bool joining, bool hotseat, TableOptions& options,
    const std::string& me, const std::vector<const client::LobbyEntry*>& recent);

}  // namespace pool::ui
