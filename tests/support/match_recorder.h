// An in-process observer for the integration tests: everything the server publishes about the
// matches on a domain, plus every shot command the players send, in arrival order.
#pragma once

#include <algorithm>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "client/net/game_client.h"
#include "net/convert.h"
#include "net/message_convert.h"
#include "net/participant.h"
#include "net/partition.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/topic.h"
#include "support/partitions.h"

namespace pool::client::test {

/// Records one domain's traffic. Poll it with pump().
class MatchRecorder {
 public:
  explicit MatchRecorder(std::uint32_t domain)
      : client_({domain, "", "recorder", {}, {}}),
        participant_(domain),
        command_topic_(participant_),
        commands_(participant_, command_topic_, net::qos::command()),
        state_topic_(participant_),
        every_match_(participant_, pool::test::everyPartition()),
        all_states_(every_match_, state_topic_, keepAll(net::qos::state())) {}

  /// Polls until `until()` holds or `timeout` passes; true when it held.
  bool pump(
      std::chrono::milliseconds timeout,
      const std::function<bool()>& until = [] { return false; }) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (true) {
      drain();
      if (until()) return true;
      if (std::chrono::steady_clock::now() >= deadline) return false;
      client_.wait(std::chrono::milliseconds(5));
    }
  }

  /// Blocks until `count` players' command writers are matched (so no command is missed).
  bool waitForPlayers(std::uint32_t count, std::chrono::milliseconds timeout) const {
    return commands_.waitForWriters(count, timeout);
  }

  const GameClient& client() const { return client_; }
  /// The first match of the lobby (lowest-numbered), or "".
  std::string firstMatch() const {
    const auto entries = client_.lobby().entries();
    return entries.empty() ? std::string() : entries.front()->match;
  }
  /// The latest state of `match` the game client accepted (signed by the pinned server key),
  /// kept after the match closed; null before any.
  const MatchView* latest(const std::string& match) const {
    const auto it = latest_.find(match);
    return it == latest_.end() ? nullptr : &it->second;
  }
  /// Every state of `match` received, in arrival order.
  std::vector<MatchView> states(const std::string& match) const {
    std::vector<MatchView> out;
    for (const auto& s : states_) {
      if (s.match == match) out.push_back(s);
    }
    return out;
  }
  /// The final report of each accepted shot of `match`, by shot number.
  std::map<std::uint32_t, ShotReport> finals(const std::string& match) const {
    std::map<std::uint32_t, ShotReport> out;
    for (const auto& r : reports_) {
      if (r.match == match && r.final()) out[r.shot_number] = r;
    }
    return out;
  }
  /// The frames of shot `shot` of `match` received, by simulated time.
  std::vector<TableFrame> frames(const std::string& match, std::uint32_t shot) const {
    std::vector<TableFrame> out;
    for (const auto& f : frames_) {
      if (f.match == match && f.shot_number == shot) out.push_back(f);
    }
    std::sort(out.begin(), out.end(),
              [](const TableFrame& a, const TableFrame& b) { return a.sim_time < b.sim_time; });
    return out;
  }
  /// Every ShotResult seen, in arrival order.
  const std::vector<ShotReport>& reports() const { return reports_; }
  /// Every rejection seen.
  std::vector<ShotReport> rejections() const {
    std::vector<ShotReport> out;
    for (const auto& r : reports_) {
      if (!r.accepted) out.push_back(r);
    }
    return out;
  }
  /// The command a seat sent with a sequence number, if seen.
  const protocol::ShotRequest* command(const std::string& match, int seat,
                                       std::uint32_t seq) const {
    const auto it = commands_seen_.find({match, seat, seq});
    return it == commands_seen_.end() ? nullptr : &it->second;
  }

  /// The `n`-th command (from 1) `seat` of `match` sent, in the order of its sequence numbers
  /// (a client numbers its seat requests and its shots alike, so shots need not start at 1).
  const protocol::ShotRequest* nthCommand(const std::string& match, int seat, std::size_t n) const {
    for (auto it = commands_seen_.lower_bound({match, seat, 0}); it != commands_seen_.end(); ++it) {
      if (std::get<0>(it->first) != match || std::get<1>(it->first) != seat) break;
      if (--n == 0) return &it->second;
    }
    return nullptr;
  }

 private:
  using CommandKey = std::tuple<std::string, int, std::uint32_t>;

  /// The state profile with every sample kept: a game client keeps the latest state only, but
  /// the replay needs each one, and under load several arrive between two polls.
  static net::QosProfile keepAll(net::QosProfile profile) {
    profile.history_depth = 0;
    return profile;
  }
  void drain() {
    for (auto& event : client_.poll()) {
      if (auto* report = std::get_if<ShotReport>(&event)) reports_.push_back(std::move(*report));
      if (auto* frame = std::get_if<TableFrame>(&event)) frames_.push_back(std::move(*frame));
    }
    for (const auto& match : observed_) {
      if (const MatchView* view = client_.state(match)) latest_[match] = *view;
    }
    // Each match travels in its own partition, and a client follows at most net::kMaxFollowed
    // (after a few server restarts more matches than that have come and gone): the recorder
    // follows the matches the lobby lists now and lets go of those that closed, keeping the
    // last state it had of each.
    std::set<std::string> listed;
    for (const auto* entry : client_.lobby().entries()) listed.insert(entry->match);
    for (auto it = observed_.begin(); it != observed_.end();) {
      if (listed.count(*it) > 0) {
        ++it;
        continue;
      }
      client_.observe(*it, false);
      it = observed_.erase(it);
    }
    for (const auto& match : listed) {
      if (observed_.insert(match).second) client_.observe(match);
    }
    for (auto& sample : all_states_.take()) {
      if (auto view = net::fromWire(*sample)) states_.push_back(std::move(*view));
    }
    for (auto& sample : commands_.take()) {
      auto request = net::fromWire(*sample);
      if (request) commands_seen_[{request->match, request->seat, request->seq}] = *request;
    }
  }

  GameClient client_;
  net::Participant participant_;
  net::Topic<pool_ShotCommand> command_topic_;
  net::Reader<pool_ShotCommand> commands_;
  net::Topic<pool_MatchState> state_topic_;
  net::Subscriber every_match_;  ///< every match's partition
  net::Reader<pool_MatchState> all_states_;
  std::vector<MatchView> states_;
  std::set<std::string> observed_;           ///< the matches followed: those listed now
  std::map<std::string, MatchView> latest_;  ///< the client's latest state of each match
  std::vector<TableFrame> frames_;
  std::vector<ShotReport> reports_;
  std::map<CommandKey, protocol::ShotRequest> commands_seen_;
};

}  // namespace pool::client::test
