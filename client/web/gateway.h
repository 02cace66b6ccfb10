// The DDS side of pool-web: one spectator session on the domain whose lobby, states, results and
// frames are fanned out to the browsers watching each match.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include "client/net/game_client.h"
#include "client/web/bounded_lobby.h"
#include "client/web/out_queue.h"

namespace pool::web {

/// How long a match nobody watches stays joined, s.
inline constexpr double kLeaveAfter = 10.0;
/// The least time between two lobby messages to every browser, s: a flood of lobby entries
/// costs a browser at most one lobby (bounded by LobbyLimits) this often.
inline constexpr double kLobbyEvery = 0.5;
/// A replay the server has not answered is asked again this often, s, and given up after
/// kReplayTries tries (the browser is told).
inline constexpr double kReplayRetry = 1.0;
inline constexpr int kReplayTries = 5;
/// Replays asked and not answered yet, at most (one a browser; past it the oldest is dropped), and
/// replay messages kept for the next browser asking for the same shot.
inline constexpr std::size_t kMaxPendingReplays = 64;
inline constexpr std::size_t kReplayCache = 16;
/// The least time between two replays one browser asks for, s.
inline constexpr double kReplayGap = 0.5;
/// The most players' records a players message carries (client::PlayerBook::fairShare), as often
/// as the lobby.
inline constexpr std::size_t kPagePlayers = 128;

/// Counters for the log and the benchmark.
struct GatewayStats {
  std::uint64_t messages = 0;  ///< messages made (each shared by every browser of its match)
  std::uint64_t deliveries = 0;
  std::uint64_t refused = 0;        ///< watch requests refused (unknown match, bad input)
  std::uint64_t lobby_refused = 0;  ///< lobby entries not kept (BoundedLobby's bounds)
};

/// Fans out one GameClient (a spectator: it sends spectate and leave requests only, never seat
/// requests or shots, and holds no seat) to browsers. Not thread-safe; time is passed in.
class Gateway {
 public:
  /// Hands a message to a browser; false when the browser cannot take it (too slow: it is then
  /// detached by the gateway, and its connection closed by the caller).
  using Sink = std::function<bool(const Message&)>;

  explicit Gateway(client::GameClient& client, double join_retry = 1.0,
                   LobbyLimits lobby_limits = {});

  /// A browser connected: it gets the lobby at once (and the players' records, if any).
  void attach(std::uint64_t browser, Sink sink);
  void detach(std::uint64_t browser);
  /// The browser watches `match` (empty: none). It gets the table, the latest state and the last
  /// shot's result at once (late join), then everything of that match. Empty when done, else why
  /// not (nothing changes then).
  std::string watch(std::uint64_t browser, const std::string& match);

  /// The browser wants stroke `shot` of `match` replayed: it gets the table's drawing and a replay
  /// message (replay_json.h) once the match's server answers (asked again every kReplayRetry s,
  /// kReplayTries times, then an error), at once when the shot was asked for lately. A browser
  /// waits for one replay at a time (a new one replaces it). Empty when asked, else why not.
  std::string replay(std::uint64_t browser, const std::string& match, std::uint32_t shot);

  /// Takes what DDS received and fans it out; sends spectate requests for newly watched matches
  /// (again every `join_retry` s until answered) and leaves matches nobody has watched for
  /// kLeaveAfter s (a browser hopping between matches makes no flood of requests); sends a
  /// changed lobby to every browser, at most every kLobbyEvery s.
  void step(double now);
  /// Fans out one event as step() does (tests feed events without DDS).
  void handle(const client::ClientEvent& event);

  std::size_t browsers() const { return browsers_.size(); }
  /// Browsers watching `match`.
  std::size_t watchers(const std::string& match) const;
  const GatewayStats& stats() const { return stats_; }
  const BoundedLobby& lobby() const { return lobby_entries_; }

 private:
  struct Watched {
    std::set<std::uint64_t> browsers;
    std::optional<std::uint32_t> request;  ///< our spectate request not answered yet
    bool joined = false;
    double sent_at = -1e9;
    std::optional<double> empty_since;  ///< when its last browser left
    Message table;                      ///< the table's drawing (once known)
    Message state;                      ///< the latest state
    Message last_result;                ///< the latest final shot result
  };
  struct Browser {
    Sink sink;
    std::string match;
    double replay_at = -1e9;  ///< when it last asked for a replay
  };

  void sendTo(std::uint64_t browser, const Message& message);
  void fanOut(const std::string& match, const Message& message);
  void sendLobby();
  /// The lobby message, made again when an entry changed since.
  const Message& lobbyMessage();
  /// The tournaments message (every tournament the client holds: at most 64), made again when
  /// one changed.
  const Message& tournamentsMessage();
  /// The players message (kPagePlayers records shared out among the server ids, each one's best
  /// rated first), made again when one changed.
  const Message& playersMessage();
  /// The table message of `match` from its lobby entry (cached by table name).
  Message tableOf(const std::string& match);
  void dropSlow();
  /// Asks the server for `match`'s stroke `shot` (again); false when the request could not go.
  bool askReplay(const std::string& match, std::uint32_t shot, std::set<std::uint64_t> browsers,
                 int tries);
  void answerReplay(const protocol::HistoryShot& shot);
  /// The table message of a table by name (cached).
  Message tableNamed(const std::string& name);

  struct PendingReplay {
    std::string match;
    std::uint32_t shot = 0;
    std::set<std::uint64_t> browsers;
    double sent_at = 0.0;
    int tries = 1;
  };

  client::GameClient& client_;
  double join_retry_;
  std::map<std::uint64_t, Browser> browsers_;
  std::map<std::string, Watched> watched_;
  std::map<std::string, Message> tables_;  ///< by table name
  BoundedLobby lobby_entries_;             ///< as the events told it, bounded
  std::map<std::string, Message> states_;  ///< the latest state of every match
  Message lobby_;
  bool lobby_stale_ = true;    ///< lobby_ must be made again
  bool lobby_changed_ = true;  ///< the browsers have not been sent the lobby as it is
  double lobby_sent_at_ = -1e9;
  Message tournaments_message_;
  bool tournaments_stale_ = true;
  bool tournaments_changed_ = false;
  double tournaments_sent_at_ = -1e9;
  Message players_;
  bool players_stale_ = true;
  bool players_changed_ = false;
  double players_sent_at_ = -1e9;
  std::set<std::uint64_t> slow_;  ///< browsers whose sink refused a message this pass
  GatewayStats stats_;
  double now_ = 0.0;                                ///< the last step's time
  std::map<std::uint32_t, PendingReplay> replays_;  ///< by history request number
  struct CachedReplay {
    Message message;
    std::string table;  ///< its table's name
  };
  std::map<std::pair<std::string, std::uint32_t>, CachedReplay> replay_cache_;
  std::deque<std::pair<std::string, std::uint32_t>> replay_order_;  ///< oldest first
};

/// What a browser may ask: to watch a match (empty: none), or a stored shot replayed.
struct WatchRequest {
  std::string match;
};
struct ReplayRequest {
  std::string match;
  std::uint32_t shot = 1;
};
using BrowserRequest = std::variant<WatchRequest, ReplayRequest>;

/// Parses a browser's request: {"watch":"<match id>"} (1–64 printable characters, or empty to
/// stop watching), or {"replay":{"match":"<match id>","shot":n}} (n from 1). Empty optional and
/// `error` set when it is neither.
std::optional<BrowserRequest> parseRequest(const std::string& text, std::string& error);

}  // namespace pool::web
