// The client's participant, topics, readers, writers and waitset, and the conversions at their
// edge.
#include "net/client_transport.h"

#include "core/text.h"

#include "net/aim_convert.h"
#include "net/convert.h"
#include "net/history_convert.h"
#include "net/match_scopes.h"
#include "net/message_convert.h"
#include "net/participant.h"
#include "net/player_stats_convert.h"
#include "net/practice_convert.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/topic.h"
#include "net/tournament_convert.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "net/writer.h"

#include <algorithm>
#include <iterator>
#include <unordered_map>
#include <utility>

namespace pool::net {
namespace {

QosProfile deeper(QosProfile profile, std::uint32_t depth = kReaderDepth) {
  profile.history_depth = depth;
  return profile;
}

enum WaitTag : std::int64_t {
  kLobby = 1,
  kReplies,
  kResults,
  kSnapshots,
  kStates,
  kAims,
  kHistory
};

/// The readers of one followed match's own topics, in its partition.
struct MatchReaders {
  MatchReaders(const Subscriber& subscriber, const ProtocolTopics& topics)
      : results(subscriber, topics.result_topic, deeper(qos::result())),
        snapshots(subscriber, topics.snapshot_topic, deeper(qos::snapshot(), kSnapshotDepth)),
        states(subscriber, topics.state_topic, deeper(qos::state())),
        cue_aims(subscriber, topics.cue_aim_topic, qos::aim()) {}
  Reader<pool_ShotResult> results;
  Reader<pool_TableSnapshot> snapshots;
  Reader<pool_MatchState> states;
  Reader<pool_CueAim> cue_aims;  ///< the shooter's cue, relayed by the server
};

}  // namespace

/// Lobby writers remembered at most (a flood of forged entries starts the map over).
constexpr std::size_t kMaxLobbyWriters = 4096;

struct ClientTransport::Endpoints : ProtocolTopics {
  Endpoints(std::uint32_t domain, ServerCheck server_check)
      : ProtocolTopics(domain),
        check(server_check ? std::move(server_check) : ServerCheck(protocol::checkSeal)),
        match_info(participant, match_info_topic, qos::lobby()),
        player_stats(participant, player_stats_topic, qos::lobby()),
        tournaments(participant, tournament_topic, qos::lobby()),
        join_replies(participant, join_reply_topic, qos::joinReply()),
        stray_results(participant, result_topic, deeper(qos::strayResult())),
        join_requests(participant, join_request_topic, qos::joinRequest()),
        commands(participant, command_topic, qos::command()),
        practice(participant, practice_topic, qos::command()),
        aim_commands(participant, aim_command_topic, qos::aim()),
        waitset(participant) {
    waitset.attachData(match_info, kLobby);
    waitset.attachData(player_stats, kLobby);
    waitset.attachData(tournaments, kLobby);
    waitset.attachData(join_replies, kReplies);
    waitset.attachData(stray_results, kResults);
  }

  /// Starts receiving `match`'s own topics; empty when followed, else why not.
  std::string open(const std::string& match) {
    auto readers = matches.open(participant, match, kMaxFollowed, [this](const Subscriber& s) {
      auto made = std::make_unique<MatchReaders>(s, *this);
      waitset.attachData(made->results, kResults);
      waitset.attachData(made->snapshots, kSnapshots);
      waitset.attachData(made->states, kStates);
      waitset.attachData(made->cue_aims, kAims);
      return made;
    });
    return readers ? std::string() : readers.error();
  }

  /// Stops receiving `match`'s own topics (what was not taken is dropped).
  void close(const std::string& match) {
    if (MatchReaders* readers = matches.find(match)) {
      waitset.detachData(readers->results);
      waitset.detachData(readers->snapshots);
      waitset.detachData(readers->states);
      waitset.detachData(readers->cue_aims);
    }
    matches.close(match);
  }

  /// Every sample `fetch(const MatchReaders&)` gives, of every followed match, in match order.
  template <class Fetch>
  auto fromEachMatch(Fetch&& fetch) const {
    decltype(fetch(std::declval<const MatchReaders&>())) all;
    matches.forEach([&](const std::string&, const MatchReaders& readers) {
      auto some = fetch(readers);
      std::move(some.begin(), some.end(), std::back_inserter(all));
    });
    return all;
  }

  /// Passes the server's `sample` where it may be read; refuses it with why it is dropped.
  template <class T>
  Check<> refusal(const T& sample) const {
    return check(sealedOf(sample));
  }

  /// Every valid sample of `samples` that passes the check, read with fromWire.
  template <class Domain, class Samples>
  std::vector<Result<Domain>> readAll(Samples samples) const {
    std::vector<Result<Domain>> out;
    for (auto& sample : samples) {
      if (!sample.meta().valid) continue;  // skips disposal notices
      if (auto ok = refusal(*sample); !ok) {
        out.push_back(Result<Domain>::fail(ok.error()));
        continue;
      }
      out.push_back(fromWire(*sample));
    }
    return out;
  }

  ServerCheck check;
  Reader<pool_MatchInfo> match_info;
  Reader<pool_PlayerStats> player_stats;
  Reader<pool_TournamentInfo> tournaments;
  Reader<pool_JoinReply> join_replies;
  /// Answers to commands naming no match or seat of the server (in the default partition).
  Reader<pool_ShotResult> stray_results;
  Writer<pool_JoinRequest> join_requests;
  Writer<pool_ShotCommand> commands;
  Writer<pool_PracticeCommand> practice;
  Writer<pool_AimCommand> aim_commands;
  /// Made by openHistory() only: a client that never replays receives no one's stored shots.
  std::unique_ptr<Writer<pool_HistoryRequest>> history_requests;
  std::unique_ptr<Reader<pool_HistoryShot>> history_shots;
  WaitSet waitset;
  /// The writer of each match's last lobby entry taken (its publication handle): only that
  /// writer's disposal of the entry is taken as the match gone.
  std::unordered_map<std::string, std::uint64_t> lobby_writers;
  MatchScopes<Subscriber, MatchReaders> matches;  ///< followed matches, each in its partition
};

ClientTransport::ClientTransport(std::uint32_t domain, ServerCheck check)
    : e_(std::make_unique<Endpoints>(domain, std::move(check))) {}

ClientTransport::~ClientTransport() = default;

void ClientTransport::wait(std::chrono::nanoseconds timeout) const {
  e_->waitset.wait(timeout);
}

std::string ClientTransport::send(const protocol::SeatRequest& request) {
  return e_->join_requests.writeOrWhy(*toWire(request));
}

std::string ClientTransport::send(const protocol::ShotRequest& command) {
  return e_->commands.writeOrWhy(*toWire(command));
}

std::string ClientTransport::send(const protocol::PracticeRequest& command) {
  return e_->practice.writeOrWhy(*toWire(command));
}

std::string ClientTransport::send(const protocol::AimSample& aim) {
  return e_->aim_commands.writeOrWhy(*toAimCommand(aim));
}

void ClientTransport::openHistory() {
  if (e_->history_requests) return;
  e_->history_requests = std::make_unique<Writer<pool_HistoryRequest>>(
      e_->participant, e_->history_request_topic, qos::command());
  e_->history_shots = std::make_unique<Reader<pool_HistoryShot>>(
      e_->participant, e_->history_shot_topic, qos::history());
  e_->waitset.attachData(*e_->history_shots, kHistory);
}

std::string ClientTransport::send(const protocol::HistoryRequest& request) {
  openHistory();
  return e_->history_requests->writeOrWhy(*toWire(request));
}

std::vector<Result<protocol::HistoryShot>> ClientTransport::takeHistory() {
  if (!e_->history_shots) return {};
  return e_->readAll<protocol::HistoryShot>(e_->history_shots->take());
}

std::vector<Result<protocol::AimSample>> ClientTransport::takeAims() {
  return e_->readAll<protocol::AimSample>(
      e_->fromEachMatch([](const MatchReaders& r) { return r.cue_aims.take(); }));
}

std::vector<Result<LobbyEvent>> ClientTransport::takeLobby() {
  std::vector<Result<LobbyEvent>> out;
  for (auto& sample : e_->match_info.takeWithNotices()) {
    std::string match(textOf(sample->match));
    if (!sample.meta().valid) {
      if (sample.meta().instance == InstanceState::Alive) continue;
      const bool disposed = sample.meta().instance == InstanceState::Disposed;
      // Anyone may dispose any instance: a disposal counts only from the writer of the entry.
      const auto writer = e_->lobby_writers.find(match);
      if (disposed && writer != e_->lobby_writers.end() &&
          writer->second != sample.meta().publication_handle) {
        out.push_back(Result<LobbyEvent>::fail("lobby entry of " + escapedForLog(match) +
                                               " disposed by a writer other than its server's: "
                                               "ignored"));
        continue;
      }
      if (writer != e_->lobby_writers.end()) e_->lobby_writers.erase(writer);
      out.push_back(Result<LobbyEvent>::ok(protocol::MatchGone{std::move(match), disposed}));
      continue;
    }
    if (auto ok = e_->refusal(*sample); !ok) {
      out.push_back(Result<LobbyEvent>::fail(ok.error()));
      continue;
    }
    auto entry = fromWire(*sample);
    if (!entry) {
      out.push_back(Result<LobbyEvent>::fail(entry.error()));
    } else if (entry->phase == protocol::MatchPhase::Closed ||
               sample.meta().instance == InstanceState::NoWriters) {
      // A signed last entry saying the match is closed, or an entry whose server went before it
      // was read: DDS then marks the entry's instance and sends no separate notice, so the
      // match is gone now. (A disposal on its own counts only from the entry's writer, above.)
      e_->lobby_writers.erase(match);
      const bool closed = entry->phase == protocol::MatchPhase::Closed;
      out.push_back(Result<LobbyEvent>::ok(protocol::MatchGone{std::move(match), closed}));
    } else {
      if (e_->lobby_writers.size() >= kMaxLobbyWriters) e_->lobby_writers.clear();
      e_->lobby_writers[match] = sample.meta().publication_handle;
      out.push_back(Result<LobbyEvent>::ok(std::move(*entry)));
    }
  }
  return out;
}

std::vector<Result<protocol::TournamentView>> ClientTransport::takeTournaments() {
  return e_->readAll<protocol::TournamentView>(e_->tournaments.take());
}

std::vector<Result<protocol::PlayerStats>> ClientTransport::takePlayerStats() {
  return e_->readAll<protocol::PlayerStats>(e_->player_stats.take());
}

std::vector<Result<protocol::JoinAnswer>> ClientTransport::takeReplies() {
  return e_->readAll<protocol::JoinAnswer>(e_->join_replies.take());
}

std::string ClientTransport::follow(const std::set<std::string>& matches) {
  std::vector<std::string> dropped;
  e_->matches.forEach([&](const std::string& match, const MatchReaders&) {
    if (!matches.count(match)) dropped.push_back(match);
  });
  for (const auto& match : dropped) e_->close(match);
  std::string problem;
  for (const auto& match : matches) {
    if (auto why = e_->open(match); !why.empty() && problem.empty()) problem = why;
  }
  return problem;
}

std::string ClientTransport::refetch(const std::string& match) {
  if (!e_->matches.find(match)) return "not followed";
  e_->close(match);
  return e_->open(match);
}

std::set<std::string> ClientTransport::followed() const {
  std::set<std::string> out;
  e_->matches.forEach([&](const std::string& match, const MatchReaders&) { out.insert(match); });
  return out;
}

std::vector<Result<protocol::MatchView>> ClientTransport::takeStates() {
  return e_->readAll<protocol::MatchView>(
      e_->fromEachMatch([](const MatchReaders& r) { return r.states.takeWithNotices(); }));
}

std::vector<Result<protocol::ShotReport>> ClientTransport::takeResults() {
  auto samples = e_->stray_results.take();
  auto followed = e_->fromEachMatch([](const MatchReaders& r) { return r.results.take(); });
  std::move(followed.begin(), followed.end(), std::back_inserter(samples));
  // A take hands samples out instance by instance (seat 0's, then seat 1's): in the order the
  // server wrote them instead, so that a seat's answer never comes out after the other seat's
  // later one.
  std::stable_sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) {
    return a.meta().source_time_ns < b.meta().source_time_ns;
  });
  return e_->readAll<protocol::ShotReport>(std::move(samples));
}

std::vector<Result<protocol::TableFrame>> ClientTransport::takeFrames() {
  return e_->readAll<protocol::TableFrame>(
      e_->fromEachMatch([](const MatchReaders& r) { return r.snapshots.take(kSnapshotDepth); }));
}

}  // namespace pool::net
