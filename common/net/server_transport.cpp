// The server's topics, readers, writers and waitset, and the conversions at their edge.
#include "net/server_transport.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "net/aim_convert.h"
#include "net/history_convert.h"
#include "net/liveliness_watch.h"
#include "net/match_scopes.h"
#include "net/message_convert.h"
#include "net/participant.h"
#include "net/player_stats_convert.h"
#include "net/practice_convert.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/shot_command_check.h"
#include "net/topic.h"
#include "net/tournament_convert.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "net/writer.h"

namespace pool::net {

namespace {

enum BusTag : std::int64_t {
  kJoinTag = 1,
  kCommandTag = 2,
  kPracticeTag = 3,
  kAimTag = 4,
  kHistoryTag = 5
};

/// More matches than any server keeps open (--max-matches bounds them): the writers of every
/// match the server publishes are kept until it disposes the match.
constexpr std::size_t kMatchWriterLimit = 1 << 16;

/// The writers of one match's own topics, in its partition.
struct MatchWriters {
  MatchWriters(const Publisher& publisher, const ProtocolTopics& topics)
      : results(publisher, topics.result_topic, qos::result()),
        snapshots(publisher, topics.snapshot_topic, qos::snapshot()),
        states(publisher, topics.state_topic, qos::state()),
        cue_aims(publisher, topics.cue_aim_topic, qos::aim()) {}
  Writer<pool_ShotResult> results;
  Writer<pool_TableSnapshot> snapshots;
  Writer<pool_MatchState> states;
  Writer<pool_CueAim> cue_aims;  ///< the shooter's cue, relayed after the server's checks
};

}  // namespace

struct ServerTransport::Endpoints : ProtocolTopics {
  Endpoints(std::uint32_t domain, const protocol::KeyPair& server_key)
      : ProtocolTopics(domain),
        key(server_key),
        join_requests(participant, join_request_topic, qos::joinRequest()),
        commands(participant, command_topic, qos::command()),
        practice(participant, practice_topic, qos::command()),
        match_info(participant, match_info_topic, qos::lobby()),
        player_stats(participant, player_stats_topic, qos::lobby()),
        join_replies(participant, join_reply_topic, qos::joinReply()),
        stray_results(participant, result_topic, qos::strayResult()),
        aim_commands(participant, aim_command_topic, qos::aimReader()),
        history_requests(participant, history_request_topic, qos::command()),
        history_shots(participant, history_shot_topic, qos::history()),
        tournaments(participant, tournament_topic, qos::lobby()),
        waitset(participant) {
    waitset.attachData(join_requests, kJoinTag);
    waitset.attachData(commands, kCommandTag);
    waitset.attachData(practice, kPracticeTag);
    waitset.attachData(aim_commands, kAimTag);
    waitset.attachData(history_requests, kHistoryTag);
  }

  /// Seals `sample` with the server's key and writes it; empty when written, else why not.
  template <class T>
  std::string sealAndWrite(const Writer<T>& writer, T& sample) const {
    seal(sample, key);
    return writer.writeOrWhy(sample);
  }

  /// The writers of `match`'s partition, made on its first sample.
  Result<MatchWriters*> writersOf(const std::string& match) {
    return matches.open(participant, match, kMatchWriterLimit, [this](const Publisher& p) {
      return std::make_unique<MatchWriters>(p, *this);
    });
  }

  protocol::KeyPair key;
  Reader<pool_JoinRequest> join_requests;
  LivelinessWatch join_liveliness{join_requests.handle()};  ///< after join_requests: it goes first
  Reader<pool_ShotCommand> commands;
  Reader<pool_PracticeCommand> practice;
  Writer<pool_MatchInfo> match_info;
  Writer<pool_PlayerStats> player_stats;
  Writer<pool_JoinReply> join_replies;
  /// Answers to commands naming no match or seat of this server, in the default partition.
  Writer<pool_ShotResult> stray_results;
  Reader<pool_AimCommand> aim_commands;
  Reader<pool_HistoryRequest> history_requests;
  Writer<pool_HistoryShot> history_shots;
  Writer<pool_TournamentInfo> tournaments;
  WaitSet waitset;
  MatchScopes<Publisher, MatchWriters> matches;  ///< per-match writers, each in its partition
  std::unordered_set<std::string> replied;       ///< clients whose last reply is kept
  /// The participant of each writer of joins and commands seen (IncomingJoin::sender), looked up
  /// once.
  std::unordered_map<std::uint64_t, std::string> senders;

  /// The sender of a sample `reader` received from `publication`.
  template <class T>
  std::string senderOf(const Reader<T>& reader, std::uint64_t publication) {
    if (const auto it = senders.find(publication); it != senders.end()) return it->second;
    const std::string guid = reader.participantOf(publication);
    if (guid.empty()) return "writer " + std::to_string(publication);
    // Writers come and go: a full cache starts again rather than keep the gone ones.
    if (senders.size() >= kMaxSenders) senders.clear();
    return senders.emplace(publication, "participant " + guid).first->second;
  }
  static constexpr std::size_t kMaxSenders = 4096;
};

ServerTransport::ServerTransport(std::uint32_t domain, const protocol::KeyPair& server_key)
    : e_(std::make_unique<Endpoints>(domain, server_key)) {}

ServerTransport::~ServerTransport() = default;

void ServerTransport::wait(std::chrono::nanoseconds timeout) const {
  e_->waitset.wait(timeout);
}

std::vector<JoinEvent> ServerTransport::takeJoins() {
  std::vector<JoinEvent> out;
  // JoinRequest has no key: its one instance's notices (a disposal anyone may write, "no writers"
  // when every client is gone) say nothing about any one client, so only data is taken.
  for (auto& sample : e_->join_requests.take()) {
    const pool_JoinRequest& r = *sample;
    std::string sender = e_->senderOf(e_->join_requests, sample.meta().publication_handle);
    auto request = fromWire(r);
    if (!request) {
      out.emplace_back(UnreadableJoin{std::string(textOf(r.client)), r.request,
                                      std::string(textOf(r.match)), request.error(),
                                      std::move(sender), sample.meta().publication_handle});
    } else {
      out.emplace_back(
          IncomingJoin{std::move(*request), std::move(sender), sample.meta().publication_handle});
    }
  }
  return out;
}

std::vector<IncomingCommand> ServerTransport::takeCommands(const protocol::CommandLimits& limits) {
  std::vector<IncomingCommand> out;
  for (auto& sample : e_->commands.take()) {
    out.push_back(readCommand(*sample, limits));
    out.back().sender = e_->senderOf(e_->commands, sample.meta().publication_handle);
  }
  return out;
}

std::vector<IncomingPractice> ServerTransport::takePractice(const protocol::CommandLimits& limits) {
  std::vector<IncomingPractice> out;
  for (auto& sample : e_->practice.take()) {
    out.push_back(readPractice(*sample, limits));
    out.back().sender = e_->senderOf(e_->practice, sample.meta().publication_handle);
  }
  return out;
}

std::vector<Result<protocol::AimSample>> ServerTransport::takeAims() {
  std::vector<Result<protocol::AimSample>> out;
  for (auto& sample : e_->aim_commands.take()) {
    if (sample.meta().valid) out.push_back(fromWire(*sample));
  }
  return out;
}

std::vector<IncomingHistory> ServerTransport::takeHistory() {
  std::vector<IncomingHistory> out;
  for (auto& sample : e_->history_requests.take()) {
    if (!sample.meta().valid) continue;
    out.push_back(IncomingHistory{
        fromWire(*sample), e_->senderOf(e_->history_requests, sample.meta().publication_handle)});
  }
  return out;
}

std::string ServerTransport::publish(const protocol::TournamentView& tournament) {
  return e_->sealAndWrite(e_->tournaments, *toWire(tournament));
}

std::string ServerTransport::publish(const protocol::HistoryShot& shot) {
  return e_->sealAndWrite(e_->history_shots, *toWire(shot));
}

std::string ServerTransport::publish(const protocol::AimSample& aim) {
  auto writers = e_->writersOf(aim.match);
  if (!writers) return writers.error();
  return e_->sealAndWrite((*writers)->cue_aims, *toCueAim(aim));
}

std::string ServerTransport::publish(const protocol::LobbyEntry& entry) {
  return e_->sealAndWrite(e_->match_info, *toWire(entry));
}

std::string ServerTransport::publish(const protocol::PlayerStats& stats) {
  return e_->sealAndWrite(e_->player_stats, *toWire(stats));
}

void ServerTransport::withdraw(const protocol::PlayerStats& stats) {
  e_->player_stats.unregister(*toWire(stats));
}

std::string ServerTransport::publish(const protocol::MatchView& view) {
  auto writers = e_->writersOf(view.match);
  if (!writers) return writers.error();
  return e_->sealAndWrite((*writers)->states, *toWire(view));
}

std::string ServerTransport::publish(const protocol::JoinAnswer& answer) {
  e_->replied.insert(answer.client);
  return e_->sealAndWrite(e_->join_replies, *toWire(answer));
}

std::string ServerTransport::publish(const protocol::ShotReport& report, bool keep) {
  auto sample = toWire(report);
  if (!keep) {
    // Not a match or seat of ours: answered where every client hears, and not kept.
    std::string error = e_->sealAndWrite(e_->stray_results, *sample);
    e_->stray_results.unregister(*sample);
    return error;
  }
  auto writers = e_->writersOf(report.match);
  if (!writers) return writers.error();
  return e_->sealAndWrite((*writers)->results, *sample);
}

std::string ServerTransport::publish(const protocol::TableFrame& frame) {
  auto writers = e_->writersOf(frame.match);
  if (!writers) return writers.error();
  return e_->sealAndWrite((*writers)->snapshots, *toWire(frame));
}

std::uint32_t ServerTransport::resultReaders(const std::string& match) {
  auto writers = e_->writersOf(match);
  return writers ? (*writers)->results.publicationMatched().current : 0;
}

std::size_t ServerTransport::matchPartitions() const {
  return e_->matches.size();
}

std::vector<std::uint64_t> ServerTransport::joinWriters() const {
  const std::vector<std::uint64_t> matched = e_->join_requests.matchedWriters();
  const std::vector<std::uint64_t> stopped = e_->join_liveliness.notAlive();
  std::vector<std::uint64_t> alive;
  std::set_difference(matched.begin(), matched.end(), stopped.begin(), stopped.end(),
                      std::back_inserter(alive));
  return alive;
}

std::uint64_t ServerTransport::joinWriterEpoch() const {
  // Each match adds one to total and current, each unmatch takes one from current: 2 total -
  // current grows by one at every one of them.
  const MatchedStatus s = e_->join_requests.subscriptionMatched();
  return 2 * std::uint64_t{s.total} - s.current + e_->join_liveliness.changes();
}

std::string ServerTransport::participantGuid() const {
  return detail::guidOf(e_->participant.handle());
}

std::size_t ServerTransport::keptReplies() const {
  return e_->replied.size();
}

void ServerTransport::forgetClient(const std::string& client) {
  pool_JoinReply key{};
  setText(key.client, client);
  // Only a client that was answered has an instance to unregister (one never answered, such as
  // a request dropped over its participant's limit, has none: unregistering it would send a notice
  // about nothing).
  if (e_->replied.erase(client) > 0) e_->join_replies.unregister(key);
}

void ServerTransport::dispose(const std::string& match) {
  pool_MatchInfo info{};
  setText(info.match, match);
  e_->match_info.dispose(info);
  MatchWriters* writers = e_->matches.find(match);
  if (!writers) return;  // nothing of it was published
  Sample<pool_MatchState> state;
  setText(state->match, match);
  writers->states.dispose(*state);
  for (const std::int16_t seat : {std::int16_t{0}, std::int16_t{1}}) {
    Sample<pool_ShotResult> result;
    setText(result->match, match);
    result->seat = seat;
    writers->results.dispose(*result);
  }
  // The disposals are on their way (a deleted writer delivers what it wrote first).
  e_->matches.close(match);
}

}  // namespace pool::net
