// The server's side of the wire: every topic as the server uses it, read and written in the
// protocol's domain types (the server itself never sees a DDS or generated type).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/result.h"
#include "net/incoming_command.h"
#include "net/incoming_practice.h"
#include "protocol/aim_sample.h"
#include "protocol/command_limits.h"
#include "protocol/history.h"
#include "protocol/key_pair.h"
#include "protocol/match_messages.h"
#include "protocol/player_stats.h"
#include "protocol/seat_request.h"
#include "protocol/shot_request.h"
#include "protocol/tournament_view.h"

namespace pool::net {

/// A join request that could not be read (an unknown action, text past its bound): the server
/// answers it with a refusal.
struct UnreadableJoin {
  std::string client;
  std::uint32_t request = 0;
  std::string match;
  std::string reason;
  std::string sender;        ///< the DDS participant it came from (IncomingJoin::sender)
  std::uint64_t writer = 0;  ///< its writer (IncomingJoin::writer)
};

/// A join request as read, with the DDS participant and the writer it came from: a client names
/// itself, but one participant sending under many client ids (from one writer or many) is still
/// one asking, and a client is present while the writer of its requests is matched
/// (ServerTransport::joinWriters).
struct IncomingJoin {
  protocol::SeatRequest request;
  /// "participant <GUID in hex>", or "writer <publication handle>" when its writer was no
  /// longer matched by the time it was read.
  std::string sender;
  std::uint64_t writer = 0;  ///< the writer's publication handle (as joinWriters lists them)
};

/// What the join-request topic delivered.
using JoinEvent = std::variant<IncomingJoin, UnreadableJoin>;

/// A history request as read (or why it could not be), with the DDS participant it came from (as
/// IncomingJoin::sender names it).
struct IncomingHistory {
  Result<protocol::HistoryRequest> request;
  std::string sender;
};

/// The server's participant, its readers of requests and commands and its writers of lobby
/// entries, replies, results, frames and states (QoS from qos_profiles.h). Lobby entries and
/// replies go out in the default partition; each match's states, results and frames in the
/// match's own (net/match_partition.h), so a client receives only the matches it follows. Every
/// sample it publishes is signed with `server_key` (net/server_seal.h). Throws DdsError from the
/// constructor only; a failed write is returned as text (empty: written).
class ServerTransport {
 public:
  ServerTransport(std::uint32_t domain, const protocol::KeyPair& server_key);
  ~ServerTransport();
  ServerTransport(const ServerTransport&) = delete;
  ServerTransport& operator=(const ServerTransport&) = delete;

  /// Blocks until a join request, command or aim arrives (or a writer is gone), or `timeout`
  /// passes.
  void wait(std::chrono::nanoseconds timeout) const;

  std::vector<JoinEvent> takeJoins();
  std::vector<IncomingCommand> takeCommands(const protocol::CommandLimits& limits);
  std::vector<IncomingPractice> takePractice(const protocol::CommandLimits& limits);
  /// The shooters' aim samples since the last take (the latest 64, whoever wrote them: the topic
  /// has no key, so a flood costs no instances; aims are cosmetic and a lost one is replaced by
  /// the next), each read with net::fromWire or why it could not be.
  std::vector<Result<protocol::AimSample>> takeAims();
  /// Requests for stored shots since the last take (the reader keeps all until taken; the server
  /// bounds what it answers).
  std::vector<IncomingHistory> takeHistory();

  std::string publish(const protocol::LobbyEntry& entry);
  /// A player's statistics and rating (kept for late readers, one sample per player and game).
  std::string publish(const protocol::PlayerStats& stats);
  /// Stops keeping the statistics of `stats`' player and game (its key fields): the writer's
  /// history stays bounded.
  void withdraw(const protocol::PlayerStats& stats);
  std::string publish(const protocol::MatchView& view);
  std::string publish(const protocol::JoinAnswer& answer);
  /// With `keep` false the result is not kept for late readers (a made-up match or seat: the
  /// writer would otherwise hold one instance per key for good).
  std::string publish(const protocol::ShotReport& report, bool keep = true);
  std::string publish(const protocol::TableFrame& frame);
  /// A tournament and its bracket (kept for late readers, one sample per tournament).
  std::string publish(const protocol::TournamentView& tournament);
  /// One stored shot, the answer to a history request (not kept for late readers).
  std::string publish(const protocol::HistoryShot& shot);
  /// Relays an aim the server accepted as a CueAim (best effort; token and signature dropped).
  std::string publish(const protocol::AimSample& aim);

  /// Readers of `match`'s shot results matched now (someone is watching it).
  std::uint32_t resultReaders(const std::string& match);
  /// Matches whose writers are open, each in its own partition (until dispose).
  std::size_t matchPartitions() const;

  /// The join-request writers alive now (IncomingJoin::writer), ascending: a writer leaves the
  /// list when its liveliness lease runs out (its process stopped or died: net::qos::kPlayerLease),
  /// when it is deleted, or when its participant's lease runs out. JoinRequest has no key, so this,
  /// not an instance per client id, is how the server knows who is still there.
  std::vector<std::uint64_t> joinWriters() const;
  /// A number that grows whenever joinWriters() may have changed (a writer matched or unmatched,
  /// lost or regained its liveliness).
  std::uint64_t joinWriterEpoch() const;
  /// The GUID of the server's DDS participant in hex (as a reader's participantOf names it).
  std::string participantGuid() const;
  /// Clients whose last join reply is kept for late readers (until forgetClient).
  std::size_t keptReplies() const;
  /// Drops the last reply kept for `client` (it is gone).
  void forgetClient(const std::string& client);
  /// Disposes `match`'s lobby entry, state and results (readers see it gone) and deletes its
  /// writers.
  void dispose(const std::string& match);

 private:
  struct Endpoints;
  std::unique_ptr<Endpoints> e_;
};

}  // namespace pool::net
