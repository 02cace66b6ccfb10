// The client's participant, topics, readers, writers and waitset, and the conversions at their
// edge.
#include "net/client_transport.h"

#include "net/aim_convert.h"
#include "net/convert.h"
#include "net/message_convert.h"
#include "net/participant.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/topic.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "net/writer.h"

namespace pool::net {
namespace {

QosProfile deeper(QosProfile profile, std::uint32_t depth = kReaderDepth) {
  profile.history_depth = depth;
  return profile;
}

enum WaitTag : std::int64_t { kLobby = 1, kReplies, kResults, kSnapshots, kStates, kAims };

}  // namespace

struct ClientTransport::Endpoints : ProtocolTopics {
  Endpoints(std::uint32_t domain, ServerCheck server_check)
      : ProtocolTopics(domain),
        check(server_check ? std::move(server_check) : ServerCheck(protocol::sealProblem)),
        match_info(participant, match_info_topic, qos::lobby()),
        join_replies(participant, join_reply_topic, qos::joinReply()),
        results(participant, result_topic, deeper(qos::result())),
        snapshots(participant, snapshot_topic, deeper(qos::snapshot(), kSnapshotDepth)),
        states(participant, state_topic, deeper(qos::state())),
        join_requests(participant, join_request_topic, qos::joinRequest()),
        commands(participant, command_topic, qos::command()),
        cue_aims(participant, cue_aim_topic, qos::aim()),
        aim_commands(participant, aim_command_topic, qos::aim()),
        waitset(participant) {
    waitset.attachData(match_info, kLobby);
    waitset.attachData(join_replies, kReplies);
    waitset.attachData(results, kResults);
    waitset.attachData(snapshots, kSnapshots);
    waitset.attachData(states, kStates);
    waitset.attachData(cue_aims, kAims);
  }

  /// Why the server's `sample` is dropped, or empty when it may be read.
  template <class T>
  std::string refusal(const T& sample) const {
    return check(sealedOf(sample));
  }

  /// Every valid sample of `samples` that passes the check, read with fromWire.
  template <class Domain, class Samples>
  std::vector<Result<Domain>> readAll(Samples samples) const {
    std::vector<Result<Domain>> out;
    for (auto& sample : samples) {
      if (!sample.meta().valid) continue;  // skips disposal notices
      if (auto why = refusal(*sample); !why.empty()) {
        out.push_back(Result<Domain>::fail(why));
        continue;
      }
      out.push_back(fromWire(*sample));
    }
    return out;
  }

  ServerCheck check;
  Reader<pool_MatchInfo> match_info;
  Reader<pool_JoinReply> join_replies;
  Reader<pool_ShotResult> results;
  Reader<pool_TableSnapshot> snapshots;
  Reader<pool_MatchState> states;
  Writer<pool_JoinRequest> join_requests;
  Writer<pool_ShotCommand> commands;
  Reader<pool_CueAim> cue_aims;
  Writer<pool_AimCommand> aim_commands;
  WaitSet waitset;
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

std::string ClientTransport::send(const protocol::AimSample& aim) {
  return e_->aim_commands.writeOrWhy(*toAimCommand(aim));
}

std::vector<Result<protocol::AimSample>> ClientTransport::takeAims() {
  return e_->readAll<protocol::AimSample>(e_->cue_aims.take());
}

std::vector<Result<LobbyEvent>> ClientTransport::takeLobby() {
  std::vector<Result<LobbyEvent>> out;
  for (auto& sample : e_->match_info.takeWithNotices()) {
    if (!sample.meta().valid) {
      if (sample.meta().instance == InstanceState::Alive) continue;
      const bool disposed = sample.meta().instance == InstanceState::Disposed;
      out.push_back(Result<LobbyEvent>::ok(
          protocol::MatchGone{std::string(textOf(sample->match)), disposed}));
      continue;
    }
    if (auto why = e_->refusal(*sample); !why.empty()) {
      out.push_back(Result<LobbyEvent>::fail(why));
      continue;
    }
    auto entry = fromWire(*sample);
    if (!entry) {
      out.push_back(Result<LobbyEvent>::fail(entry.error()));
    } else {
      out.push_back(Result<LobbyEvent>::ok(std::move(*entry)));
    }
  }
  return out;
}

std::vector<Result<protocol::JoinAnswer>> ClientTransport::takeReplies() {
  return e_->readAll<protocol::JoinAnswer>(e_->join_replies.take());
}

std::vector<Result<protocol::MatchView>> ClientTransport::takeStates() {
  return e_->readAll<protocol::MatchView>(e_->states.takeWithNotices());
}

std::vector<Result<protocol::ShotReport>> ClientTransport::takeResults() {
  return e_->readAll<protocol::ShotReport>(e_->results.take());
}

std::vector<Result<protocol::TableFrame>> ClientTransport::takeFrames() {
  return e_->readAll<protocol::TableFrame>(e_->snapshots.take(kSnapshotDepth));
}

}  // namespace pool::net
