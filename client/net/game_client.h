// The client side of the protocol, for players, bots and spectators: joining, leaving and
// rejoining matches, the lobby, shots with a per-seat sequence, and what the server publishes.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "client/net/lobby.h"
#include "client/net/match_types.h"
#include "client/net/player_book.h"
#include "client/net/server_pins.h"
#include "core/check.h"
#include "core/result.h"
#include "net/client_transport.h"
#include "protocol/aim_sample.h"
#include "protocol/history.h"
#include "protocol/key_pair.h"
#include "protocol/practice_request.h"
#include "protocol/seat_request.h"
#include "protocol/shot_request.h"
#include "protocol/tournament_view.h"

namespace pool::client {

/// Something received, as poll() hands it out.
/// A shooter's live aim (protocol::AimSample) reaches poll() only once it passed the checks of
/// GameClient::pollAims.
/// A stored shot (protocol::HistoryShot) reaches poll() only when it answers one of this client's
/// own recent history requests.
using ClientEvent = std::variant<LobbyEntry, MatchGone, JoinAnswer, MatchView, ShotReport,
                                 TableFrame, protocol::AimSample, protocol::PlayerStats,
                                 protocol::HistoryShot, protocol::TournamentView>;

/// The seat this client holds in a match.
struct SeatHolding {
  std::string match;
  int seat = -1;
  std::uint64_t token = 0;
};

/// Who the client is on the domain.
struct ClientOptions {
  std::uint32_t domain = 0;  ///< DDS domain id, 0–232
  std::string client_id;     ///< unique per process; empty: random hex
  std::string name;          ///< the player's name in seat requests
  /// Where the server keys this client trusts are pinned (server_pins.h); empty: in memory.
  std::filesystem::path server_pins;
  /// Where lines about server keys go: a pin made (`problem` false), a sample dropped (true);
  /// empty: standard error.
  std::function<void(const std::string& line, bool problem)> log;
};

/// How far past the last state a match's revision may jump, and its shot number past the last
/// one known: beyond that a sample is impossible and dropped, however it is signed.
inline constexpr std::uint32_t kMaxRevisionJump = 10000;
inline constexpr std::uint32_t kMaxShotJump = 64;

/// One client's session on a DDS domain. Not thread-safe; nothing in it reads a clock (waits
/// take a timeout). Throws net::DdsError from the constructor only.
class GameClient {
 public:
  /// `key` signs the commands of its seats (its public half goes with seat and rejoin requests);
  /// empty: a fresh pair for this session. Keep it to rejoin a seat from another process.
  explicit GameClient(ClientOptions options, std::optional<protocol::KeyPair> key = std::nullopt);
  /// How to play a table this client opens: sent with its seat requests (the server applies them
  /// only when they seat the first player at a table that has not started). Empty: the server's.
  void setTableSettings(std::optional<protocol::MatchSettings> settings) {
    table_settings_ = std::move(settings);
  }
  ~GameClient();
  GameClient(const GameClient&) = delete;
  GameClient& operator=(const GameClient&) = delete;

  const std::string& clientId() const { return options_.client_id; }
  const std::string& name() const { return options_.name; }
  const protocol::KeyPair& key() const { return key_; }

  // ---- Join requests: each returns its request number, which the answer echoes -------------
  std::uint32_t requestSeat(const std::string& match, int seat = -1);
  std::uint32_t requestSpectate(const std::string& match);
  /// Takes back `seat` (0 or 1; -1: the one bound to our key) of `match` held with `token`,
  /// proving with our key's signature that it is ours.
  std::uint32_t requestRejoin(const std::string& match, std::uint64_t token, int seat = -1);
  /// Enters the tournament `tournament` under this client's name, signed with its key (the
  /// entrant is the key).
  std::uint32_t requestEnter(const std::string& tournament);
  /// Opens a tournament of `settings`' game and race, played as `opening` says, and enters it
  /// first (signed with our key); the accepted answer names it.
  std::uint32_t requestOpenTournament(const protocol::MatchSettings& settings,
                                      const protocol::TournamentOpening& opening);
  /// Leaves the seat held (or stops watching `match` when no seat is held there).
  std::uint32_t requestLeave(const std::string& match);
  std::uint32_t requestRematch();
  /// Gives up the rack in play to the opponent (the seat held); 0 when no seat is held.
  std::uint32_t requestConcede();

  /// The seat held: set by an accepted seat or rejoin answer to one of our requests, cleared by
  /// an accepted leave.
  const std::optional<SeatHolding>& seat() const { return seat_; }

  // ---- Shots ----------------------------------------------------------------------------------
  /// Sends `request` for the seat held, filling in match, seat, token and the next sequence
  /// number, signed with the client's key. Returns the sequence number used, or why nothing was
  /// sent.
  Result<std::uint32_t> shoot(protocol::ShotRequest request);
  /// Sends a practice command for the seat held, as shoot does (the same sequence); the answer
  /// is a shot result of that number.
  Result<std::uint32_t> practice(protocol::PracticeRequest request);
  /// Makes the next sequence number larger than `seq` (after a restart, from a saved number or
  /// from the server's last result for the seat).
  void noteSequence(std::uint32_t seq);
  std::uint32_t lastSequence() const { return last_seq_; }

  // ---- Live aim -------------------------------------------------------------------------------
  /// Sends the cue of the seat held as it is aimed (cosmetic: the shot is the command's alone):
  /// fills in match, seat, token and the next aim number of the turn `aim.shot_number` (from 1
  /// each turn; apart from the commands' numbers, which it never uses up), signed with the
  /// client's key. Best effort. Returns the aim number used, or why nothing was sent.
  Result<std::uint32_t> sendAim(protocol::AimSample aim);
  /// Relayed aims dropped: not signed by the pinned server key, unreadable, not from the seat
  /// whose turn the latest state says it is, of another turn, or not newer than the last one
  /// taken for that turn (a replay). The reader keeps the latest aim per match, so a flood costs
  /// one check per match and poll.
  std::uint64_t aimDropped() const { return aim_dropped_; }

  // ---- Replays -------------------------------------------------------------------------------
  /// Opens the history endpoints now, so that the first request finds the server listening
  /// (net::ClientTransport::openHistory).
  void openHistory();
  /// Asks the server of `match` for its strokes `first` .. `first` + `count` - 1 (count up to
  /// protocol::kMaxHistoryShots), signed with the client's key; the answers come out of poll()
  /// as protocol::HistoryShot carrying the request number returned, or why nothing was sent.
  Result<std::uint32_t> requestHistory(const std::string& match, std::uint32_t first,
                                       std::uint32_t count = 1);

  // ---- Receiving ------------------------------------------------------------------------------
  /// Blocks until something arrives or `timeout` passes.
  void wait(std::chrono::nanoseconds timeout) const;
  /// Takes everything received since the last poll: lobby entries and their disappearance,
  /// answers to our own join requests, match states, shot results and frames. Updates the lobby,
  /// the seat held, the latest state of each match and the sequence floor on the way.
  std::vector<ClientEvent> poll();

  const Lobby& lobby() const { return lobby_; }
  /// The players' statistics and ratings received (PlayerStats) of the server ids the lobby lists,
  /// bounded.
  const PlayerBook& players() const { return players_; }
  /// The tournaments received, by id (the latest of each; at most kMaxTournaments, those of
  /// server ids the lobby lists).
  const std::map<std::string, protocol::TournamentView>& tournaments() const {
    return tournaments_;
  }
  static constexpr std::size_t kMaxTournaments = 64;
  /// The matches whose states, results and frames this client receives (each travels in its own
  /// DDS partition): the one it sits in, the one it watches and those its unanswered requests
  /// name. Following changes as requests go out and answers come in.
  std::set<std::string> followed() const { return transport_->followed(); }
  /// Also follows `match` without joining it (`on` false: stops), for an observer of the domain
  /// such as a test's recorder; the server does not count it as a spectator.
  void observe(const std::string& match, bool on = true);
  /// The latest state of `match`, if any arrived (only followed matches' states are kept).
  const MatchView* state(const std::string& match) const;
  /// Samples dropped because they could not be read, were not signed by their server's pinned
  /// key, or jumped impossibly far; and the last reason.
  std::uint64_t unreadable() const { return unreadable_; }
  /// Genuine samples dropped because they were older than one already taken for their match: a
  /// state of a lower revision, a result of an earlier shot for its seat, a frame of an earlier
  /// shot (a replay, or a crashed server's last sample seen late). Logged once per reason.
  std::uint64_t stale() const { return stale_; }
  const std::string& lastProblem() const { return last_problem_; }

 private:
  /// A tournament to open: its settings and how it is played.
  using Opening = std::pair<protocol::MatchSettings, protocol::TournamentOpening>;
  std::uint32_t sendJoin(const std::string& match, JoinAction action, int seat, std::uint64_t token,
                         const std::optional<Opening>& opening = {});
  /// Fills in the seat held (match, seat, token) and `seq`, signs `message` with `sign` and
  /// writes it; the sequence number sent, or why not ("<what>: <error>").
  template <class Message, class Sign>
  Result<std::uint32_t> sendSigned(Message message, std::uint32_t seq, Sign sign, const char* what);
  void pollLobby(std::vector<ClientEvent>& out);
  void pollPlayers(std::vector<ClientEvent>& out);
  void pollReplies(std::vector<ClientEvent>& out);
  void pollStates(std::vector<ClientEvent>& out);
  void pollResults(std::vector<ClientEvent>& out);
  void pollFrames(std::vector<ClientEvent>& out);
  void pollAims(std::vector<ClientEvent>& out);
  void pollHistory(std::vector<ClientEvent>& out);
  void pollTournaments(std::vector<ClientEvent>& out);
  /// Refuses a relayed aim (its seal checked) that is not taken, with why.
  Check<> checkAim(const protocol::AimSample& aim);
  struct PendingJoin {
    protocol::SeatRequest request;
    bool retried = false;  ///< sent again once after a stale-sequence answer
  };

  void send(protocol::SeatRequest& request);
  /// Follows the seat's match, the watched one and those of unanswered requests (newest first,
  /// at most net::kMaxFollowed), and forgets the states of the rest.
  void refollow();
  /// Applies an answer to one of our requests; false when it was consumed by a retry.
  bool accept(const JoinAnswer& answer);
  void problem(const std::string& what);
  /// Passes a sample the server signed, or refuses it with why it is dropped (checkSeal, then
  /// the pins: "key_changed", "bad_server_id").
  Check<> checkServer(const protocol::SealedSample& sample);
  /// Logs `line` once (the same line again is only counted).
  void note(const std::string& line, bool problem = true);
  /// Refuses a state, result or frame of `match` whose numbers jump impossibly far, with why.
  Check<> checkJump(const std::string& match, const char* what, std::uint32_t revision,
                    std::uint32_t shot_number) const;
  /// Whether a sample numbered `number` is older than `floor`, the newest taken of its kind (and
  /// then notes it as stale); otherwise raises `floor` to it.
  bool goesBack(std::uint32_t& floor, std::uint32_t number, const std::string& why);

  ClientOptions options_;
  protocol::KeyPair key_;
  ServerPins pins_;
  std::set<std::string> logged_;  ///< lines logged once (bounded)
  std::unique_ptr<net::ClientTransport> transport_;
  std::uint32_t next_request_ = 1;
  std::map<std::uint32_t, PendingJoin> pending_;  ///< our requests not answered yet
  std::optional<SeatHolding> seat_;
  std::optional<std::string> watching_;  ///< the match an accepted spectate request watches
  std::set<std::string> observed_;       ///< followed without joining (observe)
  std::uint32_t last_seq_ = 0;  ///< the last seq our key used (shots and seat requests alike)
  std::map<std::pair<std::string, int>, std::uint32_t> seen_seq_;  ///< highest seq per seat seen
  Lobby lobby_;
  PlayerBook players_;
  /// Players' records whose server id the lobby does not list yet, the latest kMaxWaitingPlayers.
  std::deque<protocol::PlayerStats> waiting_players_;
  static constexpr std::size_t kMaxWaitingPlayers = 256;
  std::map<std::string, MatchView> states_;
  std::uint64_t unreadable_ = 0;
  std::uint64_t stale_ = 0;
  /// The newest numbers taken per match (state revision, frame shot) and per seat (result shot):
  /// a sample below them is never taken again, even after the match was unfollowed and followed
  /// again. Bounded: past kMaxFloors entries each map starts over.
  std::map<std::string, std::uint32_t> state_floor_;
  std::map<std::string, std::uint32_t> frame_floor_;
  std::map<std::pair<std::string, int>, std::uint32_t> result_floor_;
  /// Per seat, the last few results taken (seq, shot, accepted, final): a genuine result replayed
  /// as it was is not older than the floor, but it is one of these. Bounded like the floors.
  struct ResultSeen {
    std::uint32_t seq = 0;
    std::uint32_t shot = 0;
    bool accepted = false;
    bool final = false;
    bool operator==(const ResultSeen&) const = default;
  };
  std::map<std::pair<std::string, int>, std::vector<ResultSeen>> results_seen_;
  static constexpr std::size_t kResultsRemembered = 8;
  static constexpr std::size_t kMaxFloors = 4096;
  /// When each match was last followed afresh because replays filled its state reader's history
  /// (a newer genuine state may have been pushed out): at most once a second per match.
  std::map<std::string, std::chrono::steady_clock::time_point> refetched_;
  std::string last_problem_;
  std::optional<protocol::MatchSettings> table_settings_;
  std::uint32_t aim_shot_ = 0;  ///< the turn our aim numbers count in
  std::uint32_t aim_seq_ = 0;   ///< the last aim number we used in it
  /// Per match, the turn and the number of the last relayed aim taken.
  std::map<std::string, std::pair<std::uint32_t, std::uint32_t>> aims_seen_;
  std::uint64_t aim_dropped_ = 0;
  std::map<std::string, protocol::TournamentView> tournaments_;
  /// Tournaments whose server the lobby does not list yet, by id.
  std::map<std::string, protocol::TournamentView> waiting_tournaments_;
  /// Our last history requests (their numbers), whose answers poll() hands out.
  std::deque<std::uint32_t> history_requests_;
  static constexpr std::size_t kHistoryRequestsKept = 64;
};

/// A random client id (hex, 16 characters).
std::string randomClientId();

}  // namespace pool::client
