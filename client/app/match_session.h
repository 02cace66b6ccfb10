// The windowed client's life on the network: one or two local seats (two on one screen) or a
// spectator, the match followed, its frames played back smoothly, and whose turn it is locally.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "client/app/aim_follower.h"
#include "client/app/instant_replay.h"
#include "client/app/playback_clock.h"
#include "client/app/recent_matches.h"
#include "client/app/shot_story.h"
#include "client/app/stored_replay.h"
#include "client/net/aim_pacer.h"
#include "client/net/game_client.h"
#include "client/net/player_identity.h"
#include "core/result.h"
#include "protocol/match_settings.h"
#include "protocol/practice_request.h"
#include "protocol/shot_request.h"

namespace pool::app {

/// Who the client is and how many seats it takes.
struct SessionOptions {
  std::uint32_t domain = 0;
  std::string name = "Player";
  bool hotseat = false;  ///< take both seats of the match: two players on one screen
  /// Where each player's key pair and held seat are kept (client/net/player_identity.h), so a
  /// restarted window takes its seat back; empty: a fresh key each run, nothing kept.
  std::filesystem::path identity_dir;
  /// How to play a table this window opens (game, race, breaks, shot clock, practice); empty:
  /// the server's defaults.
  std::optional<protocol::MatchSettings> table_settings;
};

/// What the session is doing.
enum class SessionStage : std::uint8_t {
  Lobby,       ///< choosing a match
  Joining,     ///< seat or spectator requests sent, answers pending
  Playing,     ///< seated in a match
  Spectating,  ///< watching a match
};

/// One line of what happened, for the HUD (and --json).
struct SessionNote {
  std::string text;
  bool problem = false;
};

/// Told of every frame and every shot's event log of the match followed (the window's sound).
class ShotListener {
 public:
  virtual ~ShotListener() = default;
  virtual void onFrame(const client::TableFrame& frame) = 0;
  virtual void onShot(const client::ShotReport& report) = 0;
};

class MatchSession {
 public:
  /// Throws net::DdsError when DDS cannot start.
  explicit MatchSession(SessionOptions options);
  ~MatchSession();

  /// Takes a seat (both with hotseat) in `match`, or in the lowest match with a free seat once the
  /// lobby shows one when `match` is empty.
  void play(const std::string& match = {});
  /// Watches `match`, or the first match in play ("any" or empty) once the lobby shows one.
  void spectate(const std::string& match = {});
  /// Leaves the match (seats and watching) and goes back to the lobby.
  void leave();
  /// Enters tournament `tournament` (the first seat's key and name); the answer is noted.
  void enterTournament(const std::string& tournament);
  /// Opens a tournament of `settings`' game and race, played as `opening` says, and enters it.
  void openTournament(const protocol::MatchSettings& settings,
                      const protocol::TournamentOpening& opening);
  /// The first seat's key in lower-case hex: the entrant a tournament knows this player by.
  std::string playerKey() const;

  /// Takes everything received; `now` (s, the caller's steady clock) stamps frames.
  void poll(double now);
  /// Blocks until something arrives on the first client, or `timeout` passes.
  void wait(std::chrono::nanoseconds timeout) const;

  SessionStage stage() const { return stage_; }
  const client::Lobby& lobby() const;
  /// The players' ratings and statistics received (the lobby's Players table).
  const client::PlayerBook& players() const;
  /// The matches seen played that have left the lobby since (the lobby's history).
  const RecentMatches& recent() const { return recent_; }
  /// The tournaments received (their brackets), by id.
  const std::map<std::string, protocol::TournamentView>& tournaments() const;
  const std::string& match() const { return match_; }
  /// The latest state of the match followed, if any.
  const client::MatchView* view() const;
  /// The balls to draw at `now`: the shot in motion, played back, or the layout at rest.
  std::optional<std::vector<physics::Ball>> balls(double now);
  /// True while a shot's motion is still being drawn.
  bool inMotion() const;
  /// The shot whose frames were played last, if any arrived.
  std::optional<std::uint32_t> motionShot() const { return playback_.shot(); }

  /// The seat whose player sits at this screen and may aim now (their turn, balls at rest, no shot
  /// of theirs unanswered); -1: none.
  int localShooter() const;
  /// Seats held by this screen.
  std::vector<int> localSeats() const;
  /// Sends `request` for seat `seat` (one of localSeats). Returns the sequence number.
  Result<std::uint32_t> shoot(int seat, protocol::ShotRequest request);
  /// How tables this window opens are played from now on (the lobby's options).
  void setTableSettings(std::optional<protocol::MatchSettings> settings);
  /// True when the match followed is a practice table.
  bool practiceTable() const;
  /// Sends a practice command for the first local seat of the match (a practice table). Returns
  /// the sequence number; until its answer no shot or other command is sent.
  Result<std::uint32_t> practice(protocol::PracticeRequest request);
  /// The last shot this window sent (or a loaded one, setLastShot): what "save" writes and
  /// "shoot it again from here" plays.
  const std::optional<protocol::ShotRequest>& lastShot() const { return last_shot_; }
  void setLastShot(protocol::ShotRequest shot) { last_shot_ = std::move(shot); }
  /// Sends the live aim of local seat `seat` (its turn) at `now` when the pacer says so: the cue
  /// `aim` at the cue ball `cue_ball` (m), `stroke` once released. Cosmetic and best effort: a
  /// failure is only counted (aimsNotSent).
  void sendAim(int seat, const AimState& aim, const Eigen::Vector2d& cue_ball, bool stroke,
               double now);
  /// The other shooter's cue as drawn now (a remote shooter whose relayed aims arrive), if any.
  std::optional<FollowedAim> followedAim() const;
  /// The latest relayed aim of the match followed (unsmoothed), while one is shown.
  std::optional<protocol::AimSample> latestAim() const;
  /// A remote shooter's stroke just released, handed out once.
  std::optional<FollowedAim> takeStroke() { return follower_.takeStroke(); }
  /// Relayed aims dropped so far (every client of this screen).
  std::uint64_t aimDropped() const;
  /// Live aims this screen could not send.
  std::uint64_t aimsNotSent() const { return aims_not_sent_; }
  /// Asks the server for a rematch (every local seat) after a match is over.
  void rematch();
  /// Concedes the rack in play for the local seat: the only one, or (two seats at this screen)
  /// the one to shoot. False when no local seat can concede now.
  bool concede();
  /// `listener` (or null) hears the frames and final shot reports of the match followed.
  void setListener(ShotListener* listener) { listener_ = listener; }
  /// The playback time of the shot being drawn (s since its strike).
  double playTime() const { return playback_.playTime(); }

  /// The last shot's frames and their replay (the live game's frames end a replay).
  InstantReplay& replay() { return replay_; }
  const InstantReplay& replay() const { return replay_; }

  /// Opens the replay of stored shot `shot` of any match (0: its last, the lobby's shot count
  /// asked first), asked of its server over history (the endpoints opened on the first ask; the
  /// ask sent again while unanswered). Only from the lobby, which it stands in for until
  /// closeStored (a seat or a match to watch closes it too): false elsewhere.
  bool showStored(const std::string& match, std::uint32_t shot = 0);
  void closeStored() { stored_.close(); }
  /// The stored shot asked for and shown (open while its replay stands in for the lobby).
  StoredReplay& stored() { return stored_; }
  const StoredReplay& stored() const { return stored_; }

  /// Notes since the last call: join answers, rejections, verdicts.
  std::vector<SessionNote> takeNotes();
  const std::string& lastVerdict() const { return last_verdict_; }
  /// What happened on the last shot, in sentences with names (app::shotStory), until the next
  /// shot's story replaces it; a late joiner gets the server's verdict in words.
  const std::string& banner() const { return banner_; }
  /// Every shot's story since the match was joined, oldest first (the last kLogKept).
  const std::deque<std::string>& shotLog() const { return shot_log_; }
  static constexpr std::size_t kLogKept = 200;
  /// The players' names as last seen in the match followed: a player who left (and whose seat
  /// the server freed) keeps the name they played under.
  const SeatNames& names() const { return names_; }

 private:
  void handle(client::ClientEvent& event, std::size_t from, double now);
  void onAnswer(const client::JoinAnswer& answer, std::size_t from);
  bool onRejoinAnswer(const client::JoinAnswer& answer, std::size_t from);
  void keepSeat(std::size_t from);
  void rejoinIfAway(const client::MatchView& view);
  bool joining() const;
  void sendJoin(std::size_t client);
  void retryJoins();
  void onReport(const client::ShotReport& report);
  void startPending();
  void askStored(double now);
  void note(std::string text, bool problem = false);

  SessionOptions options_;
  std::vector<std::unique_ptr<client::GameClient>> clients_;  ///< [0] also spectates
  SessionStage stage_ = SessionStage::Lobby;
  enum class Want : std::uint8_t { None, Play, Spectate } want_ = Want::None;
  std::string wanted_match_;
  std::string match_;
  std::vector<bool> awaiting_;  ///< per client: a join request not answered yet
  std::vector<std::optional<client::PlayerIdentity>> identities_;  ///< per client, if kept
  std::vector<std::optional<client::SeatRecord>> saved_;  ///< per client: a seat to take back
  std::vector<std::uint32_t> away_revision_;  ///< per client: the state that showed it away
  double join_sent_at_ = 0.0;
  PlaybackClock playback_;
  std::optional<std::uint32_t> unanswered_;  ///< a shot sent, no state or rejection for it yet
  std::uint32_t awaited_shots_ = 0;          ///< the shot number of the state that answers it
  std::uint32_t shots_seen_ = 0;             ///< the highest shot number of a state
  double frames_due_until_ = 0.0;            ///< a new shot's frames are awaited until then, s
  double last_poll_ = 0.0;
  std::string last_verdict_;
  std::string verdict_heard_;  ///< the last state's verdict, to tell a new one
  InstantReplay replay_;       ///< the last shot's frames, to play again
  StoredReplay stored_;        ///< a stored shot of any match, replayed in the lobby
  RecentMatches recent_;       ///< the lobby's history
  bool history_open_ = false;  ///< the first client's history endpoints are open
  std::string banner_;
  std::deque<std::string> shot_log_;
  SeatNames names_ = seatNames(nullptr);
  std::vector<SessionNote> notes_;
  ShotListener* listener_ = nullptr;
  std::optional<protocol::ShotRequest> last_shot_;
  AimFollower follower_;
  client::AimPacer pacer_;
  std::uint64_t aims_not_sent_ = 0;
};

}  // namespace pool::app
