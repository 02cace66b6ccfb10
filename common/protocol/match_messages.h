// The protocol's published messages in domain terms, free of DDS types: lobby entries, join
// answers, match states, shot results and table frames (the server fills them, clients read them).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "physics/ball.h"
#include "physics/events.h"
#include "protocol/match_settings.h"
#include "protocol/practice_request.h"
#include "protocol/protocol_enums.h"
#include "protocol/shot_request.h"
#include "rules/game_state.h"
#include "rules/verdict.h"

namespace pool::protocol {

/// True while a rack is being played (break, open or assigned).
bool inPlay(MatchPhase phase);

/// One match of the lobby (MatchInfo).
struct LobbyEntry {
  std::string match;  ///< "<server id>-<local number>"
  std::string server;
  std::string name;
  std::string table;  ///< table spec name, e.g. "wpa-9ft"
  MatchPhase phase = MatchPhase::Lobby;
  std::array<std::string, 2> players;  ///< empty: seat free
  int seats_taken = 0;
  std::uint32_t spectators = 0;
  std::uint32_t protocol_version = 0;
  MatchSettings settings;              ///< game, race, breaks, shot clock, practice
  std::array<int, 2> racks_won{0, 0};  ///< the score of the race
  /// Each seated player's rating in the table's game, rounded (0: a free or unsigned seat).
  std::array<int, 2> ratings{0, 0};
  std::uint32_t rack = 0;                ///< the rack (frame, game) in play, from 1; 0: none yet
  std::uint32_t shot_number = 0;         ///< shots played in the match
  std::array<int, 2> rack_points{0, 0};  ///< each seat's points in this rack (three-cushion's
                                         ///< points, snooker's frame score; 0 in pool)
  bool standard_physics = true;          ///< false: a practice table's coefficients were changed
};

/// The answer to a join request (JoinReply).
struct JoinAnswer {
  std::string client;         ///< the client that asked
  std::uint32_t request = 0;  ///< the request answered
  std::string server;
  std::string match;  ///< the match joined
  JoinAction action = JoinAction::Seat;
  JoinOutcome outcome = JoinOutcome::Accepted;
  std::string reason;          ///< empty when accepted
  int seat = -1;               ///< the seat taken; -1 for spectators and refusals
  std::uint64_t token = 0;     ///< the seat's token; 0 for spectators and refusals
  std::uint32_t last_seq = 0;  ///< the last seq the request's key used on that server

  bool accepted() const { return outcome == JoinOutcome::Accepted; }
};

/// One seat of a match state.
struct SeatView {
  std::string name;  ///< empty: free
  bool connected = false;
  rules::Group group = rules::Group::None;
  int balls_left = 0;
  int fouls = 0;
  int racks_won = 0;
  std::uint32_t last_seq = 0;  ///< the seat's last used sequence number
  int fouls_in_row = 0;        ///< 9-/10-ball: fouls on its consecutive shots (three lose)
  int extensions_left = 0;     ///< shot clock extensions left this rack
  int points = 0;              ///< three-cushion: points this game; snooker: the frame score
  int innings = 0;             ///< three-cushion: innings completed this game
  int high_run = 0;  ///< three-cushion: the most points in one inning; snooker: the highest break
  int misses = 0;    ///< snooker: misses in a row with a ball on in plain view (three lose)
};

/// A match between shots (MatchState).
struct MatchView {
  std::string match;
  std::uint32_t revision = 0;
  MatchPhase phase = MatchPhase::Lobby;
  std::array<SeatView, 2> seats;
  int shooter = -1;  ///< seat to shoot or choose; -1: none
  int breaker = -1;
  std::uint32_t rack = 0;
  std::uint32_t shot_number = 0;
  rules::BallInHand ball_in_hand = rules::BallInHand::None;
  std::vector<rules::Choice> options;  ///< the shooter must choose one first
  double shot_clock = -1.0;            ///< s left; < 0: no clock (or not running)
  double shot_clock_total = 0.0;       ///< s the current shot has in all (extension included)
  int winner = -1;
  rules::GameEnd end = rules::GameEnd::None;
  std::string last_verdict;
  std::vector<physics::Ball> balls;     ///< the layout at rest, pocketed balls included
  MatchSettings settings;               ///< game, race, breaks, shot clock, practice
  bool standard_physics = true;         ///< false: a practice table's coefficients were changed
  PracticeCoefficients coefficients{};  ///< the table's, in kPracticeCoefficients' order
  int undo_depth = 0;                   ///< practice: shots the table can undo
  int run = 0;             ///< three-cushion: the points of the inning so far; snooker: the break
  int cue_ball = 0;        ///< the ball the shooter strikes (three-cushion: 0 white, 1 yellow)
  int ball_on = 0;         ///< snooker: rules::kOnRed, kOnColour or the colour's id
  bool free_ball = false;  ///< snooker: the shooter plays a free ball

  /// The warning is on: the clock runs and little time is left.
  bool clockWarning() const {
    return shot_clock >= 0.0 && settings.clockOn() && shot_clock <= settings.warningAt();
  }
};

/// The rules' state of a match view in play (phase, shooter, breaker, groups, ball in hand,
/// options; dry turns are not on the wire).
rules::GameState gameStateOf(const MatchView& view);

/// An answer to a shot command (ShotResult): the immediate acceptance or rejection, or the final
/// report of an accepted shot with its events and verdict.
struct ShotReport {
  std::string match;
  int seat = 0;
  std::uint32_t seq = 0;
  std::uint32_t shot_number = 0;
  bool accepted = false;
  RejectReason reject_reason = RejectReason::None;
  std::string reject_text;
  physics::EventLog events;
  std::vector<rules::Foul> fouls;
  std::vector<int> pocketed;
  bool turn_continues = false;
  int next_shooter = -1;
  rules::BallInHand ball_in_hand = rules::BallInHand::None;
  std::vector<rules::Choice> options;
  bool game_over = false;
  int winner = -1;
  rules::GameEnd end = rules::GameEnd::None;
  std::string verdict_text;
  int scored = 0;  ///< points the shot scored (three-cushion)

  /// True for the report that closes an accepted command (its verdict is known). The immediate
  /// acceptance of a stroke carries neither events nor a verdict text.
  bool final() const { return accepted && (!verdict_text.empty() || !events.empty()); }
  /// True when the server used up the seat's sequence number with this command: accepted, or
  /// refused by a check after the signature's (server/README.md). A refusal before it (token,
  /// unsigned, bad signature, stale, malformed fields) may answer anyone's command.
  bool usesUpSequence() const;
};

/// Every ball of one match at one instant of a shot (TableSnapshot).
struct TableFrame {
  std::string match;
  std::uint32_t frame = 0;  ///< from 0 at the strike
  double sim_time = 0.0;    ///< s since the strike
  std::uint32_t shot_number = 0;
  std::vector<physics::Ball> balls;
};

/// A match's lobby entry or state went away: the server closed it or stopped answering.
struct MatchGone {
  std::string match;
  bool disposed = false;  ///< true: closed by the server; false: its writer vanished
};

}  // namespace pool::protocol
