// The server's single loop: wait on DDS, answer joins and commands, publish frames and state.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "net/server_transport.h"
#include "protocol/command_limits.h"
#include "server/admin/admin_listener.h"
#include "server/admin_desk.h"
#include "server/heap_trim.h"
#include "server/history_desk.h"
#include "server/join_tally.h"
#include "server/match/aim_gate.h"
#include "server/match/join_rate_limit.h"
#include "server/match/match_registry.h"
#include "server/match/match_replay.h"
#include "server/player_publish.h"
#include "server/presence.h"
#include "server/rejection_tally.h"
#include "server/server_config.h"
#include "server/server_counters.h"
#include "server/store/match_store.h"
#include "server/tournament_desk.h"

namespace pool::server {

/// Serves every match of `registry` over `transport` from one thread. Each pass reads the monotonic
/// clock once and hands that `now` to the match logic; nothing blocks on one match (frames in
/// flight are published as their time comes, while other matches go on).
///
/// Presence: players and spectators keep their JoinRequest writer for the session; its automatic
/// liveliness lease (net::qos::kPlayerLease) runs out when the process stops or dies, and it is
/// deleted on a clean exit. Either way every client the server answered from that writer is gone
/// (presence.h), and its seats go away for `grace` seconds.
class ServerLoop {
 public:
  /// With a `store`, every accepted command is committed to it before its result is published,
  /// and every visible change of a match is saved before it is published.
  ServerLoop(const ServerConfig& config, MatchRegistry& registry, net::ServerTransport& transport,
             store::MatchStore* store = nullptr);

  /// Plays `replay` on this loop: its commands are answered and published like players' ones.
  void replay(MatchReplay* replay) { replay_ = replay; }

  /// Serves the operator: each pass ends by answering the requests `listener` received through
  /// `desk`, then stores and publishes what they changed.
  void admin(admin::AdminListener* listener, AdminDesk* desk) {
    admin_ = listener;
    desk_ = desk;
  }

  /// The tournaments this server runs (restored from the store when the loop is made).
  TournamentDesk& tournaments() { return tournaments_; }

  /// What the loop has counted so far.
  const ServerCounters& counters() const { return counters_; }
  /// The live aims relayed and dropped so far.
  const AimGate& aims() const { return aims_; }

  /// Checks `check(now)` after every pass; a non-empty answer ends run() with it as fault().
  void guard(std::function<std::string(double now)> check) { guard_ = std::move(check); }
  /// Why run() ended on its own (a guard's answer), or empty.
  const std::string& fault() const { return fault_; }
  /// Runs passes until `stop` is set (checked at least every kMaxWait) or a guard objects.
  void run(const std::atomic<bool>& stop);

  /// One pass at `now` (s since the loop started): joins, commands, due frames, grace expiries,
  /// then the lobby entries and states of the matches that changed.
  void step(double now);

  /// Disposes every match's lobby entry and state (shutdown: readers see them gone).
  void disposeAll();

  /// Seconds on the monotonic clock since the loop was made.
  double now() const;

  /// The longest wait for DDS in one pass.
  static constexpr std::chrono::milliseconds kMaxWait{20};

 private:
  void readJoins(double now);
  /// Answers a join request from `sender` (net::IncomingJoin), within its client's and its
  /// participant's limits.
  void answerJoin(const JoinCommand& command, const std::string& sender, std::uint64_t writer,
                  double now);
  /// Publishes `answer` to `to`'s client and tracks the client's presence from `writer` (tied to
  /// it when `seated`, Presence::answered).
  void reply(const JoinCommand& to, const JoinAnswer& answer, const std::string& sender,
             std::uint64_t writer, bool seated, double now);
  /// Lets go of the clients whose join-request writer is gone or not alive (when the writers
  /// changed, or a client was tied to a writer since), and once a second unties the clients no
  /// seat names.
  void sweepPresence(double now);
  /// `gone` is gone: its seats go away for the grace period, its reply and join bucket are dropped.
  void letGo(const Presence::Gone& gone, double now, const char* why);
  /// Whether a join request from `sender` is within its participant's limit; one over it is
  /// counted, and refused with a reply to `echo`'s client at most once a second (the rest go
  /// unanswered: each reply is an instance the server writes).
  bool withinSenderLimit(const std::string& sender, std::uint64_t writer, const JoinCommand& echo,
                         double now);
  /// The key of a client's join-rate bucket: its id as sent by `sender`.
  static std::string senderClient(const std::string& sender, const std::string& client);
  /// Clients the server holds something for: kept replies and per-client join buckets (not the
  /// per-participant buckets: one per DDS participant that asked lately, however many ids it
  /// sent under, each gone once full again).
  std::size_t trackedClients() const;
  void warnIfFailed(const std::string& error, const char* what) const;
  void readCommands(double now);
  /// Practice commands: checked, carried out, answered (never stored).
  void readPractice(double now);
  /// Relays the shooters' aims that pass the gate (aim_gate.h); drops the rest, counted.
  void relayAims(double now);
  void publishFrames(double now);
  /// Whether `match` is one of this server's and `seat` one of its seats (0 or 1).
  bool ourSeat(const std::string& match, int seat) const;
  void publishResult(const std::string& match, const CommandAnswer& answer);
  /// Counts and answers a refusal of a command from `sender` (IncomingSigned::sender).
  void refused(const std::string& match, const CommandAnswer& answer, double now,
               const std::string& sender);
  /// Publishes the state and lobby entry of every match that changed, and the lobby entry of
  /// one whose spectators changed (at most once a kSpectatorCountPeriod).
  void publishChanges(double now);
  /// Each seated player's rating in the match's game, from the store, into its lobby entry.
  void addRatings(const Match& match, protocol::LobbyEntry& entry);
  void storeShot(const CommandAnswer& answer, const std::string& match);
  void stepReplay(double now);
  /// Answers the requests for stored shots (history_desk.h); without a store, drops them.
  void answerHistory(double now);
  /// Runs the tournaments (their results, their next matches) and publishes those that changed.
  void stepTournaments(double now);
  void storeChanges(const std::vector<std::string>& closed);
  /// Sends a match's last lobby entry again, saying it is closed: a client that reads the entry
  /// and its disposal in one take sees only the entry (DDS sends no separate notice then).
  void publishClosing(const std::string& match);
  void dispose(const std::string& match);
  void serveAdmin(double now);
  /// Runs `write` (one transaction) and counts the time it took.
  template <class Write>
  double timedCommit(Write&& write);
  std::chrono::nanoseconds waitTimeout(double now) const;

  ServerConfig config_;
  MatchRegistry& registry_;
  net::ServerTransport& transport_;
  protocol::CommandLimits limits_;
  store::MatchStore* store_;
  PlayerPublisher players_;             ///< the players' records (PlayerStats)
  std::optional<HistoryDesk> history_;  ///< answers history requests (with a store only)
  TournamentDesk tournaments_;          ///< the tournaments, their matches opened in registry_
  MatchReplay* replay_ = nullptr;
  bool replay_reported_ = false;
  bool replay_started_ = false;  ///< a spectator has been seen: the replay runs
  /// What was last published of a match.
  struct Published {
    std::uint64_t revision = 0;
    std::size_t spectators = 0;
    double info_at = -1e9;                      ///< when its lobby entry went out
    std::optional<protocol::LobbyEntry> entry;  ///< the lobby entry that went out last
  };
  std::map<std::string, Published> published_;   ///< by match id
  std::map<std::string, std::uint64_t> stored_;  ///< match id -> revision last stored
  std::uint64_t stored_opened_ = 0;              ///< the match counter as last stored
  admin::AdminListener* admin_ = nullptr;
  AdminDesk* desk_ = nullptr;
  ServerCounters counters_;
  AimGate aims_;                 ///< the checks on live aims
  double aims_logged_ = 0.0;     ///< when the aim counts were last logged, s
  std::uint64_t aims_seen_ = 0;  ///< aims dropped at that time
  RejectionTally rejections_;    ///< refused commands: one info line a second, each at debug
  JoinTally joins_;              ///< spectators and refused joins: likewise
  HeapTrim heap_trim_;           ///< gives a flood's freed heap back once it is over
  /// Join requests per client id from one DDS participant (keyed by both): a client id is
  /// anyone's to write, so a flood under a player's id empties the flooder's bucket, not hers.
  JoinRateLimit rate_;
  /// Each answered client, present while its join-request writer is matched.
  Presence presence_;
  double untied_at_ = 0.0;  ///< when presence_ last untied clients that hold no seat, s
  std::uint64_t join_writer_epoch_ = 0;  ///< transport_.joinWriterEpoch() at the last sweep
  /// Join requests per DDS participant: one that asks under many client ids (a flood), from one
  /// writer or many, is limited as one. Twice a client's rate: a program may run a few clients.
  JoinRateLimit sender_rate_{2 * JoinRateLimit::kPerSecond, 2 * JoinRateLimit::kBurst};
  /// Answers to commands that name no match or seat of this server, per DDS participant: each
  /// answer is a sample keyed by a match id the sender chose, which the DDS writer pays for, so a
  /// flood of invented ids is answered a few times a second, not command by command.
  JoinRateLimit stray_answers_{JoinRateLimit::kPerSecond, JoinRateLimit::kBurst};
  std::chrono::steady_clock::time_point epoch_;
  std::optional<double> last_step_;  ///< when the previous pass ran, s
  double file_checked_ = 0.0;        ///< when the store's file was last checked, s
  std::function<std::string(double)> guard_;
  std::string fault_;
  /// A pass later than this after the previous one means the server was not running.
  static constexpr double kStall = 1.0;
  /// A lobby entry whose only change is its spectator count goes out at most this often, s.
  static constexpr double kSpectatorCountPeriod = 1.0;
  /// Players' records published at start: the most recently counted.
  static constexpr std::size_t kPlayersAtStart = 64;
};

}  // namespace pool::server
