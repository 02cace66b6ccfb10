// An adversary on the DDS domain for tests: a participant of its own that publishes crafted
// MatchInfo, MatchState, ShotResult and TableSnapshot samples, unsigned or signed by any key.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "net/participant.h"
#include "net/partition.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/sample.h"
#include "net/server_seal.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "protocol/key_pair.h"
#include "protocol/protocol_version.h"
#include "support/partitions.h"

namespace pool::test {

/// Writes forged server samples. With a key, each is sealed as a server would seal it (the key
/// carried is that key's); without one, unsigned. Every write first waits (bounded) for the
/// readers it targets, so a test knows the sample went out to them.
class Forger {
 public:
  explicit Forger(std::uint32_t domain)
      : bus_(domain),
        everywhere_(bus_.participant, pool::test::everyPartition()),
        infos_(everywhere_, bus_.match_info_topic, net::qos::lobby()),
        states_(everywhere_, bus_.state_topic, net::qos::state()),
        results_(everywhere_, bus_.result_topic, net::qos::result()),
        snapshots_(everywhere_, bus_.snapshot_topic, net::qos::snapshot()) {}

  /// Waits for `count` readers of each topic before a write (all the clients a test means to hit).
  void expectReaders(std::uint32_t count) { readers_ = count; }

  /// Signs what follows with `key`; std::nullopt: unsigned.
  void signWith(std::optional<protocol::KeyPair> key) { key_ = std::move(key); }

  /// A lobby entry of `match` by `server`.
  bool publishInfo(const std::string& server, const std::string& match) {
    net::Sample<pool_MatchInfo> s;
    net::setText(s->match, match);
    net::setText(s->server, server);
    net::setText(s->name, "forged");
    net::setText(s->table, "wpa-9ft");
    s->phase = pool_PHASE_OPEN;
    s->protocol_version = protocol::kProtocolVersion;
    s->game = 8;
    s->race_to = 1;
    return write(infos_, *s);
  }

  /// A state of `match`: over, seat `winner` won by forfeit, at `revision` and `shot_number`.
  bool publishState(const std::string& match, std::uint32_t revision, std::uint32_t shot_number,
                    pool_MatchPhase phase = pool_PHASE_OVER, std::int16_t winner = 1) {
    net::Sample<pool_MatchState> s;
    net::setText(s->match, match);
    s->revision = revision;
    s->phase = phase;
    net::setText(s->seats[0].name, "Ada");
    net::setText(s->seats[1].name, "Mallory");
    s->shooter = -1;
    s->breaker = 0;
    s->rack = 1;
    s->shot_number = shot_number;
    s->shot_clock = -1.0;
    s->game = 8;  // a well-formed state in every field but what it lies about
    s->race_to = 1;
    s->winner = winner;
    s->end = pool_END_FORFEIT;
    net::setText(s->last_verdict, "forged: seat 2 wins");
    return write(states_, *s);
  }

  /// A final report of a shot of `match` by `seat`: game over, `seat` the winner.
  bool publishResult(const std::string& match, std::int16_t seat, std::uint32_t shot_number) {
    net::Sample<pool_ShotResult> s;
    net::setText(s->match, match);
    s->seat = seat;
    s->seq = 1;
    s->shot_number = shot_number;
    s->accepted = true;
    s->next_shooter = -1;
    s->game_over = true;
    s->winner = seat;
    s->end = pool_END_EIGHT_POCKETED;
    net::setText(s->verdict_text, "forged: the 8 went in");
    return write(results_, *s);
  }

  /// A frame of `match` with every ball at (x, 0) and the cue ball among them.
  bool publishFrame(const std::string& match, std::uint32_t shot_number, double x = 0.5) {
    net::Sample<pool_TableSnapshot> s;
    net::setText(s->match, match);
    s->frame = 0;
    s->sim_time = 0.0;
    s->shot_number = shot_number;
    auto balls = net::resizeSequence(s->balls, 1);
    balls[0].id = 0;
    balls[0].state = pool_MOTION_STATIONARY;
    balls[0].pos = {x, 0.0, 0.028575};
    balls[0].orient = {1.0, 0.0, 0.0, 0.0};
    return write(snapshots_, *s);
  }

 private:
  template <class T>
  bool write(const net::Writer<T>& writer, T& sample) {
    if (!writer.waitForReaders(readers_, std::chrono::seconds(30))) return false;
    if (key_) net::seal(sample, *key_);
    return static_cast<bool>(writer.write(sample));
  }

  net::ProtocolTopics bus_;
  /// The default partition and every match's: partitions keep nobody out, the forged samples
  /// reach each client that follows the match they name.
  net::Publisher everywhere_;
  net::Writer<pool_MatchInfo> infos_;
  net::Writer<pool_MatchState> states_;
  net::Writer<pool_ShotResult> results_;
  net::Writer<pool_TableSnapshot> snapshots_;
  std::optional<protocol::KeyPair> key_;
  std::uint32_t readers_ = 1;
};

}  // namespace pool::test
