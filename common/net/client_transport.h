// A player's or spectator's side of the wire: the protocol's topics read and written in domain
// types (clients never see a DDS or generated type).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "core/result.h"
#include "protocol/aim_sample.h"
#include "protocol/history.h"
#include "protocol/match_messages.h"
#include "protocol/player_stats.h"
#include "protocol/practice_request.h"
#include "protocol/seat_request.h"
#include "protocol/server_signature.h"
#include "protocol/shot_request.h"
#include "protocol/tournament_view.h"

namespace pool::net {

/// How deep the client's readers keep results and states per instance, so that a slow poll does
/// not lose the acceptance of a shot behind its final report, or a state behind the next one.
inline constexpr std::uint32_t kReaderDepth = 16;
/// Snapshots kept per match between polls: an unpaced server (--fast) sends a shot's frames in a
/// burst, and a spectator counting them should see most of them.
inline constexpr std::uint32_t kSnapshotDepth = 512;

/// The most matches one client follows at once (a player's, a spectator's, a few pending asks).
inline constexpr std::size_t kMaxFollowed = 16;

/// A lobby entry, or the news that one went away.
using LobbyEvent = std::variant<protocol::LobbyEntry, protocol::MatchGone>;

/// Decides whether a sample the server signed may be read: passes it, or refuses it with why it is
/// dropped (the sample then comes out of the take as a failure with that reason).
using ServerCheck = std::function<Check<>(const protocol::SealedSample&)>;

/// One participant with every reader and writer a client needs, and a waitset over the readers.
/// The lobby and join replies are read in the default partition; the states, results and frames
/// of the matches the client follows (follow) in each match's own partition, so nothing of
/// another match reaches it.
/// Throws DdsError from the constructor only. Each take returns what arrived since the last one,
/// a sample that could not be read or that `check` refused as a failure naming why. Without a
/// check, a sample is read when its signature verifies with the key it carries
/// (protocol::checkSeal); a client that pins server keys passes its own.
class ClientTransport {
 public:
  explicit ClientTransport(std::uint32_t domain, ServerCheck check = {});
  ~ClientTransport();
  ClientTransport(const ClientTransport&) = delete;
  ClientTransport& operator=(const ClientTransport&) = delete;

  /// Blocks until some reader has data or `timeout` passes.
  void wait(std::chrono::nanoseconds timeout) const;

  /// Writes a join request (the writer stays for the whole session: its liveliness tells the
  /// server we are here). Empty when written, else why not.
  std::string send(const protocol::SeatRequest& request);
  std::string send(const protocol::ShotRequest& command);
  std::string send(const protocol::PracticeRequest& command);

  /// Receives the states, results and frames of exactly `matches` from now on, each in its own
  /// partition. A match newly followed delivers its latest state and results at once
  /// (transient-local); one no longer named is dropped with whatever of it was not taken. A
  /// match id that names no partition, or past kMaxFollowed, is not followed: the first such
  /// reason is returned (empty: all followed).
  std::string follow(const std::set<std::string>& matches);
  /// Tournaments since the last take (TournamentInfo), each checked as the lobby is.
  std::vector<Result<protocol::TournamentView>> takeTournaments();
  /// Players' statistics and ratings since the last take (PlayerStats), each checked as the lobby
  /// is.
  std::vector<Result<protocol::PlayerStats>> takePlayerStats();
  std::set<std::string> followed() const;
  /// Follows the followed `match` afresh (its readers made again, what was not taken dropped):
  /// its latest state and results come again from the writers' histories, as when first
  /// followed. Empty when done, else why not.
  std::string refetch(const std::string& match);

  /// Opens the history request writer and the reader of stored shots (once; send does it too, but
  /// a request written before the server's reader has matched the new writer is lost: open early).
  void openHistory();
  /// Writes a signed request for stored shots (opening the history endpoints if need be).
  std::string send(const protocol::HistoryRequest& request);
  /// Stored shots since the last take, anyone's answers (each names its client and request),
  /// checked as the lobby is; none before openHistory().
  std::vector<Result<protocol::HistoryShot>> takeHistory();

  /// Writes the shooter's signed aim (best effort: it may be lost, the next one replaces it).
  std::string send(const protocol::AimSample& aim);

  std::vector<Result<LobbyEvent>> takeLobby();
  std::vector<Result<protocol::JoinAnswer>> takeReplies();
  /// Match states; a disposed one is skipped (the lobby reports the match gone).
  std::vector<Result<protocol::MatchView>> takeStates();
  /// Results of the followed matches, and refusals of commands naming no match of the server.
  std::vector<Result<protocol::ShotReport>> takeResults();
  std::vector<Result<protocol::TableFrame>> takeFrames();
  /// Shooters' aims the server relayed (CueAim), the latest per match.
  std::vector<Result<protocol::AimSample>> takeAims();

 private:
  struct Endpoints;
  std::unique_ptr<Endpoints> e_;
};

}  // namespace pool::net
