// pool-bot's life on the network: finding a match, taking (or taking back) a seat, playing its
// turns with the AI, noticing a lost server, and ending with the result.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "client/bot/ai/bot_level.h"
#include "client/bot/ai/shot_planner.h"
#include "client/bot/ai/skill_noise.h"
#include "client/bot/ai/table_view.h"
#include "client/net/aim_pacer.h"
#include "client/net/game_client.h"
#include "client/net/seat_file.h"

namespace pool::bot {

/// What the bot was told on the command line.
struct BotConfig {
  std::string match;  ///< a match id; empty: the lowest-numbered with a free seat
  /// How well it plays: a level's execution noise and planning (the default), or with `skill`
  /// the older aim and speed error of a skill 0..1 (1 = none) and exact planning.
  Level level = kDefaultLevel;
  std::optional<double> skill;
  std::uint64_t seed = 1;           ///< seeds the execution noise
  std::filesystem::path seat_file;  ///< where the seat and its token are kept; empty: nowhere
  double join_retry = 1.0;          ///< s between join attempts while unanswered
  double lost_seat_wait = 5.0;   ///< s a lobby is seen without the lost match before seating anew
  double answer_timeout = 10.0;  ///< s without an answer to a shot before sending it again
  double think = 0.0;            ///< s to wait on each turn before shooting (pace for watchers)
  /// Tests: think the full `think` even when the shot clock runs out first (it shoots
  /// kClockMargin s before the clock's end otherwise).
  bool ignore_shot_clock = false;
  /// Concedes every rack from this one on (the match's rack number, from 1) on its first turn in
  /// it instead of shooting; 0: never.
  std::uint32_t concede_from_rack = 0;
  /// At game over, asks for a rematch and plays it, as long as its opponent keeps their seat;
  /// leaves once they leave. Off: the bot is done at game over.
  bool stay = false;
};

/// How long before the shot clock runs out the bot shoots at the latest (planning, delivery), s.
inline constexpr double kClockMargin = 2.0;

/// Where the bot is in its life.
enum class BotStage : std::uint8_t {
  FindingMatch,  ///< no seat: waiting for a server and a match with a free seat
  Joining,       ///< a seat or rejoin request is out
  Playing,       ///< seated: shooting when it is our turn
  SeatLost,      ///< the server or the match went away: waiting to rejoin
  Finished,      ///< the match is over (resultLine says how)
  Failed,        ///< the server refused us for good (failure says why)
};

const char* toString(BotStage stage);

/// Plays one match through `client`. Time is passed in (s on any monotonic clock).
class BotPlayer {
 public:
  BotPlayer(client::GameClient& client, BotConfig config, std::optional<client::SeatRecord> saved);

  /// Handles what arrived since the last step and acts on it.
  void step(double now);

  BotStage stage() const { return stage_; }
  bool done() const { return stage_ == BotStage::Finished || stage_ == BotStage::Failed; }
  /// "result: win 1-0 (eight_pocketed after 23 shots)" once finished.
  const std::string& resultLine() const { return result_line_; }
  const std::string& failure() const { return failure_; }

 private:
  void handle(const client::ClientEvent& event, double now);
  void onAnswer(const client::JoinAnswer& answer, double now);
  void onLobby(const client::LobbyEntry& entry, double now);
  void onGone(const client::MatchGone& gone, double now);
  void onState(const client::MatchView& view, double now);
  void onReport(const client::ShotReport& report, double now);

  void act(double now);
  void findMatch(double now);
  void sendJoin(double now);
  void maybeShoot(double now);
  void loseSeat(double now, const std::string& why);
  void finish(const client::MatchView& view);
  /// With `stay`: asks once per game over for a rematch.
  void askRematch(const client::MatchView& view);
  /// "result: win 1-0 (...)" of the game over `view`, for our seat.
  std::string resultOf(const client::MatchView& view) const;
  void saveSeat();
  bool myTurn(const client::MatchView& view) const;
  /// The plan of this turn's state (made once per state: the think time shows it being aimed).
  const PlannedShot& planFor(const client::MatchView& view);
  /// `cue` as the bot's hand plays it: moved by its level's noise (the planner's) or its skill's
  /// error.
  physics::CueShot played(const physics::CueShot& cue);
  /// Sends the cue as it is aimed `progress` (0–1) into the think time (paced).
  void showAim(const client::MatchView& view, const PlannedShot& shot, double progress, bool stroke,
               double now);
  const TableView* tableFor(const std::string& match);

  client::GameClient& client_;
  BotConfig config_;
  std::optional<client::SeatRecord>
      saved_;  ///< the seat to take back (from a file or a lost server)
  BotStage stage_ = BotStage::FindingMatch;
  std::string target_;  ///< the match being joined or played
  std::optional<std::uint32_t> join_request_;
  double join_sent_at_ = -1e9;
  double lost_at_ = 0.0;
  std::optional<double> lobby_seen_at_;  ///< when this lobby first listed a match
  /// A server's lobby entries arrive one by one in no set order: a table is chosen once they
  /// have had this long (s) to come in, so that two bots started together both see the lowest
  /// free table and meet at it.
  static constexpr double kLobbySettle = 0.3;

  // The shot in flight: its sequence number, when it left, the state it was planned on.
  std::optional<std::uint32_t> pending_seq_;
  double shot_sent_at_ = 0.0;
  std::uint32_t shot_revision_ = 0;
  std::uint32_t wait_for_shot_ = 0;  ///< after an accepted shot: play again once state has it
  std::optional<std::uint32_t> blocked_revision_;  ///< a rejection said: wait for a new state
  double retry_at_ = 0.0;
  std::optional<std::uint32_t> turn_revision_;  ///< the state our current turn was first seen in
  double turn_since_ = 0.0;
  std::optional<double> clock_deadline_;  ///< when the shot clock of our turn runs out (our clock)
  int rejections_ = 0;
  std::optional<std::uint32_t> away_revision_;    ///< the state that showed us away (we rejoined)
  std::uint32_t conceded_rack_ = 0;               ///< the last rack conceded (--concede-from-rack)
  std::optional<std::uint32_t> concede_request_;  ///< a concession awaiting its answer

  std::optional<PlannedShot> plan_;               ///< the plan of the state below
  std::uint32_t plan_revision_ = 0;               ///< the state it was made on
  std::optional<std::uint32_t> stroke_revision_;  ///< the state whose stroke was shown
  client::AimPacer pacer_;                        ///< the live aim's sends

  std::map<std::string, std::unique_ptr<TableView>> tables_;
  std::unique_ptr<ShotPlanner> planner_;
  std::string planner_table_;
  PlannerOptions planner_options_;  ///< the planner's, its level's noise among them
  SkillNoise noise_;                ///< with a skill
  Rng level_rng_;                   ///< with a level: the draws of its noise
  std::string result_line_;
  bool rematch_asked_ = false;  ///< the game over on the table has our rematch request
  std::string failure_;
};

}  // namespace pool::bot
