// What the player asks of the match at the window: a game, a rematch, a bot, the replay...
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/bot/ai/bot_level.h"
#include "client/ui/bot_opponent.h"
#include "client/ui/eight_ball_room_ui.h"
#include "client/ui/lobby_screen.h"
#include "client/ui/window_notes.h"
#include "client/ui/window_turn.h"

namespace pool::ui {

/// The match's requests and what they keep between frames: the concession's question, the
/// lobby's table options, the bot wanted and the one running, the room.
class MatchDesk {
 public:
  /// `domain`: the DDS domain a bot opponent is started on.
  MatchDesk(app::MatchSession& session, app::Controls& controls, TurnDesk& turn, WindowNotes& notes,
            std::uint32_t domain);

  /// Leaves a finished match for a free table (the server keeps one open).
  void newGame();
  /// A rematch, unless the opponent has left the table (then the player is told so).
  void rematch();
  /// Plays the last shot again at `speed` × real time (never while the balls move).
  void startReplay(double speed, double now);

  /// True when a player at this screen may concede the rack in play (between shots).
  bool canConcede() const;
  /// Asks the player whether to concede, when a rack may be conceded.
  void askConcede() { concede_asked_ = canConcede(); }
  /// Drops the question once the rack may no longer be conceded.
  void dropStaleQuestion();
  /// Q was pressed: the concession waits for Y or Esc.
  bool concedeAsked() const { return concede_asked_; }
  /// The player's yes or no to conceding the rack.
  void answerConcede(bool yes);

  /// A practice table of this window's own, at once.
  void playPractice();
  /// Asks for a fresh table of the lobby's options; a bot of `level` takes its other seat once
  /// this window holds its own (startBotOpponent).
  void playBot(bot::Level level);
  /// Starts the bot wanted, at the match this window was seated in.
  void startBotOpponent();
  /// Carries out the lobby's `choice` with its table options.
  void takeLobbyChoice(const LobbyChoice& choice);
  /// Starts a bot of `level` that enters `tournament` and plays its matches there while the
  /// window stays (kMaxEntrantBots at most).
  void addTournamentBot(const std::string& tournament, bot::Level level);
  static constexpr std::size_t kMaxEntrantBots = 31;
  /// Takes the seat of the tournament match that calls this player (once each), from the lobby
  /// or a decided match; elsewhere (a game in play, a practice table) tells them once.
  void answerTournamentCall();
  /// The lobby's options for a fresh table.
  TableOptions& tableOptions() { return table_options_; }

  /// The winner is in the Magic Eight Ball room.
  bool inRoom() const { return in_room_; }
  void setInRoom(bool in) { in_room_ = in; }
  EightBallRoomState& room() { return room_; }

 private:
  app::MatchSession& session_;
  app::Controls& controls_;
  TurnDesk& turn_;
  WindowNotes& notes_;
  std::uint32_t domain_;
  bool concede_asked_ = false;
  TableOptions table_options_;
  std::optional<bot::Level> bot_wanted_;  ///< a bot to start once this window holds its seat
  BotOpponent bot_opponent_;
  std::vector<std::unique_ptr<BotOpponent>> entrant_bots_;  ///< bots entered in tournaments
  int bots_named_ = 0;
  std::set<std::string> called_;  ///< tournament matches this window took its seat in
  std::set<std::string> told_;    ///< tournament matches the player was told of, away
  bool in_room_ = false;
  EightBallRoomState room_;
};

}  // namespace pool::ui
