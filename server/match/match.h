// One match: two seats, spectators, the rules' state, the balls at rest, and its command handling.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "physics/simulation.h"
#include "protocol/match_settings.h"
#include "protocol/practice_request.h"
#include "protocol/seat_request.h"
#include "protocol/shot_request.h"
#include "rules/game_rules.h"
#include "rules/game_state.h"
#include "server/match/command_check.h"
#include "server/match/frame_pacer.h"
#include "server/match/join.h"
#include "server/match/match_snapshot.h"
#include "server/match/match_types.h"
#include "server/match/seat.h"
#include "server/match/shot_runner.h"

namespace pool::server {

/// Frames handed out by Match::takeDueFrames: frame numbers first, first + 1, ... of one shot.
struct DueFrames {
  std::uint32_t first = 0;        ///< the number of frames[0] (0 at the strike)
  std::uint32_t shot_number = 0;  ///< the shot they belong to
  std::span<const physics::Sample> frames;
};

/// One match of 8-, 9- or 10-ball, a race to one or more racks. Pure logic: time comes in as `now`
/// (s on the server's monotonic clock), shots are simulated at once and their frames handed out as
/// `now` reaches them. Every refused command leaves it unchanged, except that one its seat's key
/// signed uses up its sequence number.
class Match {
 public:
  /// A new match whose racks `generator` lays out from `rack_seed`.
  Match(std::string id, std::string name, std::shared_ptr<ShotRunner> runner, MatchOptions options,
        std::uint64_t rack_seed, table::RackGenerator generator = table::kCurrentRackGenerator);
  /// A match resumed from `snapshot` (a restarted server): its seated players are away since
  /// `now`, so the grace period starts at the resume.
  Match(const MatchSnapshot& snapshot, std::shared_ptr<ShotRunner> runner, MatchOptions options,
        double now);

  // ---- Seats and spectators (the registry checks names, versions and ids first) -------------

  /// Seats `player` (client `client`) in `seat` (0, 1, or -1 for the first free one) with
  /// `token` (non-zero), binding `public_key` to it: the seat's commands and requests must be
  /// signed with it (the registry checked the seat request's signature) and carry the token.
  /// The client already in that seat with that key gets it back unchanged (a repeated request);
  /// a seat bound to that key whose player is away (a tournament's reserved seat, a player who
  /// dropped out) is given back to `client`, present again.
  /// Starts a rack when both seats are taken and no game is in play. `settings` (checked by the
  /// registry) apply when this player is the first to sit at a table that has not started.
  JoinAnswer takeSeat(int seat, const std::string& player, const std::string& client,
                      std::uint64_t token, const std::vector<std::uint8_t>& public_key,
                      const std::optional<protocol::MatchSettings>& settings = {});
  /// Seats the two players a tournament drew for this table that has not started (names, keys and
  /// tokens; seat 0 is the bracket's entrant a), each away from `now` until they take their seat
  /// (takeSeat with that key gives it back), and starts the first rack with `settings` (checked):
  /// a player who does not come within the grace period forfeits, as one who left. `spots`: the
  /// racks each seat starts the race with (a handicap; each below the race). Refused when the
  /// table has started or a seat is taken, or the game cannot be played here.
  Check<> reserveSeats(const std::array<std::string, 2>& players,
                       const std::array<std::vector<std::uint8_t>, 2>& keys,
                       const std::array<std::uint64_t, 2>& tokens,
                       const protocol::MatchSettings& settings, double now,
                       const std::array<int, 2>& spots = {0, 0});
  /// Keeps this table's seats for `keys` for good (seat 0, seat 1): any other key is refused a
  /// seat, a decided race starts no new rack and no rematch (a tournament's table; a restarted
  /// server says so again after resuming it).
  void reserveKeys(const std::array<std::vector<std::uint8_t>, 2>& keys) { reserved_ = keys; }
  bool reserved() const { return !reserved_[0].empty(); }
  /// A request that changes a held seat (Rejoin, Leave, Rematch, Concede), checked in this order:
  /// the seat (the one named, or the one bound to the request's key) → the holding's token (public,
  /// but a request signed for an earlier holding of the seat never matches it) → unsigned
  /// → stale sequence → signature by the seat's key. Once the signature checks out the sequence
  /// number is used up, even if the request is then refused. Rejoin gives the seat back to
  /// `request.client`, present again; Leave frees it (a game in play is forfeited to the other
  /// seat); Rematch asks for a new rack once the match is over (it starts when both asked);
  /// Concede gives the rack in play to the other seat, between shots only (the race goes on
  /// with the next rack, or the match is over if that rack won it).
  JoinAnswer seatRequest(const protocol::SeatRequest& request);
  /// `client` watches (counted once however often it asks).
  JoinAnswer addSpectator(const std::string& client);
  /// `client` stops watching; false when it was not.
  bool removeSpectator(const std::string& client);

  /// The server was not running (stopped, suspended) for `seconds`: that time counts against
  /// nobody. Away seats' grace and the frames in flight are pushed back by it.
  void pause(double seconds);
  /// `client` vanished at `now`: its seats wait for it (away), it stops watching. True when it
  /// held a seat here.
  bool clientGone(const std::string& client, double now);
  /// Whether a seat here names `client` (away or not).
  bool seats(const std::string& client) const;
  /// Forfeits a game in play to the other seat when a seat's player has been away `grace` s or
  /// more by `now` (once the shot in motion, if any, is done); in the lobby, or once the match is
  /// over, such a seat is freed. True when it acted.
  bool expireAway(double now, double grace);

  // ---- Shot clock -----------------------------------------------------------------------------

  /// Runs the shot clock at `now` (s, server clock): starts it for a new turn (once the shooter's
  /// view has shown the last shot to rest), gives the shooter's one extension of the rack when it
  /// first runs out, and otherwise judges the expiry: a foul, the cue ball in hand to the
  /// opponent. Returns that verdict's answer (stored and published like a choice); empty when
  /// nothing was judged.
  std::optional<CommandAnswer> tickClock(double now);
  /// Seconds left for the shooter at `now`; empty while no clock runs (none set, no rack in
  /// play, a shot in motion).
  std::optional<double> clockLeft(double now) const;
  /// Judges the shooter's clock as run out now, whatever it shows (a replay of a stored expiry);
  /// empty when no rack is in play or a shot is in motion.
  std::optional<CommandAnswer> runOutClock();
  /// Seconds the current shot has in all (an extension included).
  double clockTotal() const { return clock_total_; }
  /// Shot clock extensions `seat` has left this rack.
  int extensionsLeft(int seat) const { return extensions_[static_cast<std::size_t>(seat)]; }

  // ---- Shots ----------------------------------------------------------------------------------

  /// Checks `command` (see command_check.h for the order) and, if accepted, simulates the shot
  /// (its frames are then due from `now` on) or applies the choice. The registry has already
  /// checked the wire fields and the match id.
  CommandAnswer handleShot(const protocol::ShotRequest& command, double now);

  /// The frames of the shot in motion due by `now` and not handed out before (empty when none).
  DueFrames takeDueFrames(double now);
  /// When the next frame is due (s); empty when no shot is in motion or all frames are out.
  std::optional<double> nextFrameDue() const;
  /// Once every frame of the shot in motion was handed out: commits the shot (balls, state) and
  /// returns its report. Empty otherwise.
  std::optional<ShotReport> finishShot();
  /// True while a shot's frames are being published.
  bool inMotion() const { return flight_.has_value(); }
  /// The shot number of the shot in motion (0 when none).
  std::uint32_t shotInMotion() const;

  // ---- Practice (match_practice.cpp) ---------------------------------------------------------

  /// True for a practice table (its settings say so): its seated players shoot as they like, the
  /// cue ball always in hand anywhere, nothing is a foul, and practice commands change its table.
  bool practice() const { return settings_.practice; }
  /// Checks `command` like a shot command (seat, token, unsigned, stale sequence, signature:
  /// from there on its number is used up), then: closed → not a practice table → balls moving →
  /// the action's own checks (a legal layout of the game's balls with the cue ball, a rack of a
  /// game of this table, something to undo, a last shot to play again, coefficients in their
  /// ranges). Refused with nothing changed; accepted, the answer is done at once, except
  /// Again's, a shot in motion like handleShot's.
  CommandAnswer handlePractice(const protocol::PracticeRequest& command, double now);
  /// False once a practice table's coefficients were changed.
  bool standardPhysics() const { return !custom_physics_; }
  /// Changes a practice table can undo.
  std::size_t undoDepth() const { return history_.size(); }

  // ---- State ----------------------------------------------------------------------------------

  const std::string& id() const { return id_; }
  const std::string& name() const { return name_; }
  const game::LoadedTable& table() const { return runner_->kit(); }
  MatchPhase phase() const;
  const std::array<Seat, 2>& seats() const { return seats_; }
  std::size_t spectators() const { return spectators_.size(); }
  const rules::GameState& game() const { return game_; }
  /// Every ball at rest (pocketed ones too), id order.
  const std::vector<physics::Ball>& balls() const { return balls_; }
  std::uint32_t shotNumber() const { return shot_number_; }
  std::uint32_t rack() const { return rack_; }
  const std::string& lastVerdict() const { return last_verdict_; }
  const MatchOptions& options() const { return options_; }
  /// Game, race, breaks and shot clock of this match.
  const protocol::MatchSettings& settings() const { return settings_; }
  /// The rule set this match is judged by.
  rules::GameRules rules() const { return {settings_.game, options_.rules, {settings_.points}}; }
  /// The ball the shooter strikes from `state`: rules::cueBallFor (three-cushion: the shooter's
  /// own ball), but at a practice table always the cue ball (three-cushion's white), whichever
  /// seat shoots, as the practice rules judge it.
  int cueBallFor(const rules::GameState& state) const;
  /// Increases with every change of the match itself (state, seats, presence), each stored and
  /// published; spectators coming and going are not changes of the match (see spectators()).
  std::uint64_t revision() const { return revision_; }
  /// True while a rack is in play (not lobby, not over).
  bool inPlay() const;
  /// True once the match is closed.
  bool closed() const { return closed_; }
  /// Replaces the rack's rules state and balls at rest (a restored match, a test position). Only
  /// between shots of a started match; false otherwise.
  bool setPosition(const rules::GameState& state, std::vector<physics::Ball> balls);
  /// Marks the match closed (no more commands or joins); a non-empty `why` becomes the last
  /// verdict its players read (an operator's close).
  void close(std::string why = {});
  /// True when nobody sits or watches.
  bool empty() const;
  /// The match as plain data, as it stands once the shot in motion (if any) is done.
  MatchSnapshot snapshot() const;

 private:
  struct Flight {
    ShotReport report;
    std::vector<physics::Sample> frames;  ///< the trajectory, then the table at rest
    std::vector<physics::Ball> after;     ///< the table at rest once the verdict is applied
    FramePacer pacer;
    double view_done = 0.0;  ///< when the shooter's view has shown the shot to rest (s)
  };

  /// A change of a practice table that undo takes back: the table and state before it, and for
  /// a shot, the command and its checked plan (to play it again).
  struct PracticeStep {
    std::vector<physics::Ball> balls;
    rules::GameState game;
    std::optional<protocol::ShotRequest> command;
    std::optional<ShotPlan> plan;
  };

  /// The runner of `game`'s table (options().tables), or this match's when there are none.
  Result<std::shared_ptr<ShotRunner>> runnerFor(rules::Game game) const;
  /// The match's rack number `number` (from 0) of `game`: each number racks the same every time.
  std::vector<physics::Ball> layout(std::uint64_t number, rules::Game game) const;
  CommandAnswer accept(const protocol::ShotRequest& command);
  /// Runs a checked shot (handleShot, or a practice table's Again) and puts it in motion.
  CommandAnswer runPlan(const protocol::ShotRequest& command, ShotPlan plan, double now);
  /// The rules' verdict on `shot` played from `state` (practice rules at a practice table).
  Result<rules::Verdict> judge(const rules::GameState& state, const rules::Shot& shot) const;
  void startPractice();
  void rememberStep(std::optional<protocol::ShotRequest> command, std::optional<ShotPlan> plan);
  Rejection practiceChange(const protocol::PracticeRequest& command);
  CommandAnswer applyChoiceNow(const protocol::ShotRequest& command, const rules::Verdict& verdict,
                               std::vector<physics::Ball> after);
  void land(Flight flight);
  void startRack(int breaker);
  void commit(const rules::Verdict& verdict, std::vector<physics::Ball> after, int shooter);
  void forfeitSeat(int loser, const std::string& why);
  std::vector<physics::Ball> tableAfter(const rules::Verdict& verdict,
                                        std::vector<physics::Ball> balls);
  std::optional<int> seatOf(const protocol::SeatRequest& request) const;
  JoinAnswer rejoinSeat(int seat, const std::string& client);
  JoinAnswer leaveSeat(int seat);
  JoinAnswer rematchSeat(int seat);
  JoinAnswer concedeSeat(int seat);
  void touch() { ++revision_; }
  void restartClock(double not_before);
  CommandAnswer timeOut();
  /// Who breaks the next rack of the race, `rack_winner` having won the last one.
  int nextBreaker(int rack_winner) const;

  std::string id_;
  std::string name_;
  std::shared_ptr<ShotRunner> runner_;
  MatchOptions options_;
  std::uint64_t rack_seed_;
  std::uint64_t layouts_ = 0;  ///< racks laid out so far (each from its own seed)
  /// How its racks are laid out: the generator of the program that opened it.
  table::RackGenerator rack_generator_ = table::kCurrentRackGenerator;
  std::array<Seat, 2> seats_{};
  std::array<std::vector<std::uint8_t>, 2> reserved_{};  ///< reserveKeys
  std::set<std::string> spectators_;
  bool started_ = false;
  bool closed_ = false;
  rules::GameState game_;
  std::vector<physics::Ball> balls_;
  std::uint32_t shot_number_ = 0;
  std::uint32_t rack_ = 0;
  std::string last_verdict_;
  std::uint64_t revision_ = 1;
  std::optional<Flight> flight_;
  std::optional<int> pending_forfeit_;  ///< a seat to forfeit once the shot in motion is done
  protocol::MatchSettings settings_;
  // The shot clock: pending until the next tick starts it (not before clock_not_before_).
  bool clock_pending_ = false;
  double clock_not_before_ = 0.0;
  std::optional<double> clock_start_;
  double clock_total_ = 0.0;
  bool clock_warned_ = false;
  std::array<int, 2> extensions_{0, 0};
  // A practice table: what undo takes back (oldest first), and its own physics once changed.
  std::vector<PracticeStep> history_;
  bool custom_physics_ = false;
  std::optional<protocol::PracticeCoefficients>
      standard_coefficients_;  ///< before the first change
};

}  // namespace pool::server
