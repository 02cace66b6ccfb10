// A player or spectator for integration tests: its own DDS participant talking to a server.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "net/convert.h"
#include "net/messages.h"
#include "net/participant.h"
#include "net/partition.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/topic.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "protocol/command_signature.h"
#include "protocol/key_pair.h"
#include "protocol/seat_request.h"
#include "protocol/shot_request.h"
#include "support/partitions.h"

namespace pool::server::test {

using namespace std::chrono_literals;

/// A profile that keeps every sample in this reader (so a test can look at each one in turn).
inline net::QosProfile keepAll(net::QosProfile profile) {
  profile.history_depth = 0;
  return profile;
}

/// One client: writes joins and commands, and records every reply, result, state, lobby entry
/// and frame it receives (in deques, so pointers to them stay valid). Every wait is bounded.
class TestClient {
 public:
  TestClient(std::uint32_t domain, std::string id)
      : id_(std::move(id)),
        bus_(domain),
        join_writer_(bus_.participant, bus_.join_request_topic, net::qos::joinRequest()),
        command_writer_(bus_.participant, bus_.command_topic, net::qos::command()),
        infos_(bus_.participant, bus_.match_info_topic, keepAll(net::qos::lobby())),
        replies_(bus_.participant, bus_.join_reply_topic, keepAll(net::qos::joinReply())),
        every_match_(bus_.participant, pool::test::everyPartition()),
        results_(every_match_, bus_.result_topic, keepAll(net::qos::result())),
        strays_(bus_.participant, bus_.result_topic, keepAll(net::qos::strayResult())),
        snapshots_(every_match_, bus_.snapshot_topic, keepAll(net::qos::snapshot())),
        states_(every_match_, bus_.state_topic, keepAll(net::qos::state())),
        waitset_(bus_.participant) {
    waitset_.attachData(infos_, 1);
    waitset_.attachData(replies_, 2);
    waitset_.attachData(results_, 3);
    waitset_.attachData(snapshots_, 4);
    waitset_.attachData(states_, 5);
    waitset_.attachData(strays_, 6);
  }

  const std::string& id() const { return id_; }
  /// The key pair whose public half this client's seat and rejoin requests carry.
  const protocol::KeyPair& key() const { return key_; }
  /// Uses `key` from now on (e.g. a restarted player's kept key).
  void useKey(const protocol::KeyPair& key) { key_ = key; }

  /// Pumps the readers until `done()` holds or `timeout` passes; returns done().
  bool waitUntil(const std::function<bool()>& done, std::chrono::milliseconds timeout = 10s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    pump();
    while (!done()) {
      if (std::chrono::steady_clock::now() >= deadline) return false;
      waitset_.wait(20ms);
      pump();
    }
    return true;
  }

  /// Waits until the server's lobby shows at least `matches` matches (the server is up and seen).
  bool waitForServer(std::size_t matches = 1, std::chrono::milliseconds timeout = 15s) {
    const bool seen = waitUntil([&] { return liveInfos() >= matches; }, timeout);
    return seen && join_writer_.waitForReaders(1, timeout) &&
           command_writer_.waitForReaders(1, timeout);
  }

  /// Sends a join request and waits for its reply. Requests that change a seat are signed with
  /// this client's key and numbered with its next sequence number.
  std::optional<pool_JoinReply> join(pool_JoinAction action, const std::string& match,
                                     const std::string& name = "", short seat = -1,
                                     std::uint64_t token = 0,
                                     std::uint32_t version = protocol::kProtocolVersion) {
    protocol::SeatRequest r = request(action, match, name, seat, token);
    r.protocol_version = version;
    if (protocol::changesSeat(r)) {
      r.seq = ++seq_;
      protocol::signSeatRequest(r, key_);
    }
    return joinAsIs(r);
  }

  /// A join request from this client, unsigned, with the next request number.
  protocol::SeatRequest request(pool_JoinAction action, const std::string& match,
                                const std::string& name = "", short seat = -1,
                                std::uint64_t token = 0) {
    protocol::SeatRequest r;
    r.client = id_;
    r.request = ++requests_;
    r.protocol_version = protocol::kProtocolVersion;
    r.match = match;
    r.action = static_cast<protocol::JoinAction>(static_cast<int>(action));
    r.seat = seat;
    r.name = name;
    r.token = token;
    r.public_key = key_.publicKey();
    return r;
  }

  /// Writes `r` exactly as given (whatever its key, number and signature) and waits for the
  /// reply to its request number.
  std::optional<pool_JoinReply> joinAsIs(const protocol::SeatRequest& r) {
    net::Sample<pool_JoinRequest> sample;
    pool_JoinRequest& w = *sample;
    net::setText(w.client, r.client);
    w.request = r.request;
    w.protocol_version = r.protocol_version;
    net::setText(w.match, r.match);
    w.action = static_cast<pool_JoinAction>(static_cast<int>(r.action));
    w.seat = static_cast<std::int16_t>(r.seat);
    net::setText(w.name, r.name);
    w.seat_token = r.token;
    net::setBytes(w.public_key, r.public_key, protocol::kPublicKeyBytes);
    w.seq = r.seq;
    net::setBytes(w.signature, r.signature, protocol::kSignatureBytes);
    pump();
    const std::size_t from = replies.size();  // a replayed request's answer is a new sample
    EXPECT_TRUE(join_writer_.write(w));
    std::optional<pool_JoinReply> reply;
    waitUntil([&] {
      for (std::size_t i = from; i < replies.size(); ++i) {
        const auto& s = replies[i];
        if (s->request == r.request && net::textOf(s->client) == r.client) reply = *s;
      }
      return reply.has_value();
    });
    return reply;
  }

  /// The last sequence number this client used for a seat request; sets the next one's floor.
  std::uint32_t seq() const { return seq_; }
  void setSeq(std::uint32_t seq) { seq_ = seq; }

  /// Writes a join request as given, without waiting for its reply.
  void writeJoin(const pool_JoinRequest& request) { EXPECT_TRUE(join_writer_.write(request)); }

  /// Writes a shot command as given.
  void send(const pool_ShotCommand& command) { EXPECT_TRUE(command_writer_.write(command)); }
  void sendAsIs(const protocol::ShotRequest& request) {
    seq_ = std::max(seq_, request.seq);  // later seat requests number above it
    send(*net::toWire(request));
  }
  /// Signs `request` with this client's key and writes it.
  void send(protocol::ShotRequest request) {
    protocol::signCommand(request, key_);
    sendAsIs(request);
  }

  /// How many results are recorded: pass it to waitResult to look only at later ones.
  std::size_t mark() const { return results.size(); }

  /// The first result recorded at index `from` or later for (`match`, `seat`, `seq`) that
  /// satisfies `also`, waiting for it; null on timeout.
  const pool_ShotResult* waitResult(const std::string& match, int seat, std::uint32_t seq,
                                    const std::function<bool(const pool_ShotResult&)>& also,
                                    std::size_t from = 0, std::chrono::milliseconds timeout = 10s) {
    const pool_ShotResult* found = nullptr;
    waitUntil(
        [&] {
          for (std::size_t i = from; i < results.size(); ++i) {
            const pool_ShotResult& r = *results[i];
            if (net::textOf(r.match) == match && r.seat == seat && r.seq == seq && also(r)) {
              found = &r;
              return true;
            }
          }
          return false;
        },
        timeout);
    return found;
  }

  /// The first answer (accepted or not) to a command recorded from index `from` on.
  const pool_ShotResult* waitAnswer(const std::string& match, int seat, std::uint32_t seq,
                                    std::size_t from = 0) {
    return waitResult(
        match, seat, seq, [](const pool_ShotResult&) { return true; }, from);
  }

  /// The final result of an accepted command (with its verdict), waiting for it.
  const pool_ShotResult* waitFinal(const std::string& match, int seat, std::uint32_t seq,
                                   std::chrono::milliseconds timeout = 20s) {
    return waitResult(
        match, seat, seq,
        [](const pool_ShotResult& r) { return r.accepted && r.verdict_text[0] != '\0'; }, 0,
        timeout);
  }

  /// The latest recorded MatchState of `match`, or null.
  const pool_MatchState* latestState(const std::string& match) const {
    const pool_MatchState* latest = nullptr;
    for (const auto& s : states) {
      if (net::textOf(s->match) == match) latest = s.get();
    }
    return latest;
  }

  /// Waits until the latest MatchState of `match` satisfies `ok`; returns it (or null).
  const pool_MatchState* waitState(const std::string& match,
                                   const std::function<bool(const pool_MatchState&)>& ok,
                                   std::chrono::milliseconds timeout = 10s) {
    waitUntil(
        [&] {
          const auto* s = latestState(match);
          return s && ok(*s);
        },
        timeout);
    const auto* s = latestState(match);
    return s && ok(*s) ? s : nullptr;
  }

  /// Recorded states of `match` (each match's own: another match's writers are discovered on
  /// their own time, since each match publishes in a partition of its own).
  std::size_t stateCount(const std::string& match) const {
    std::size_t n = 0;
    for (const auto& s : states) n += net::textOf(s->match) == match;
    return n;
  }

  /// Recorded frames of `match`.
  std::size_t snapshotCount(const std::string& match) const {
    std::size_t n = 0;
    for (const auto& s : snapshots) n += net::textOf(s->match) == match;
    return n;
  }

  /// How many distinct matches the recorded lobby entries name.
  std::size_t liveInfos() const {
    std::vector<std::string> ids;
    for (const auto& s : infos) {
      const std::string id(net::textOf(s->match));
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    }
    return ids.size();
  }

  std::deque<net::Sample<pool_MatchInfo>> infos;
  std::deque<net::Sample<pool_JoinReply>> replies;
  std::deque<net::Sample<pool_ShotResult>> results;
  std::deque<net::Sample<pool_TableSnapshot>> snapshots;
  std::deque<net::Sample<pool_MatchState>> states;
  std::vector<std::string> disposed_infos;  ///< match ids whose lobby entry was disposed

 private:
  template <class T>
  static void drain(const net::Reader<T>& reader, std::deque<net::Sample<T>>& into) {
    for (auto& s : reader.take()) into.push_back(std::move(s));
  }

  void pump() {
    for (auto& s : infos_.takeWithNotices()) {
      // A disposal that comes before the entry's last sample is read marks that sample's
      // instance, with no notice of its own.
      if (s.meta().instance == net::InstanceState::Disposed) {
        disposed_infos.emplace_back(net::textOf(s->match));
      }
      if (s.meta().valid) infos.push_back(std::move(s));
    }
    drain(replies_, replies);
    drain(results_, results);
    drain(strays_, results);
    drain(snapshots_, snapshots);
    drain(states_, states);
  }

  std::string id_;
  protocol::KeyPair key_ = protocol::generateKeyPair();
  std::uint32_t requests_ = 0;
  std::uint32_t seq_ = 0;    ///< the last sequence number this client's key used
  net::ProtocolTopics bus_;  ///< the participant and the protocol's topics
  net::Writer<pool_JoinRequest> join_writer_;
  net::Writer<pool_ShotCommand> command_writer_;
  net::Reader<pool_MatchInfo> infos_;
  net::Reader<pool_JoinReply> replies_;
  net::Subscriber every_match_;  ///< the default partition and every match's
  net::Reader<pool_ShotResult> results_;
  /// Refusals of commands naming no match or seat of the server's (volatile, default partition).
  net::Reader<pool_ShotResult> strays_;
  net::Reader<pool_TableSnapshot> snapshots_;
  net::Reader<pool_MatchState> states_;
  net::WaitSet waitset_;
};

}  // namespace pool::server::test
