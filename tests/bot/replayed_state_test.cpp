// A stranger captures a genuine, server-signed MatchState off the wire and replays it over the
// live match later on: the players drop it as older than what they have, and the match goes on;
// replayed more often than a reader keeps, it hides no newer state from a client; and a genuine
// ShotResult replayed is taken once.
#include <gtest/gtest.h>

#include <optional>
#include <thread>

#include "net/client_transport.h"
#include "net/partition.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/sample.h"
#include "net/writer.h"
#include "support/client_fixture.h"
#include "support/partitions.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

/// These tests' DDS domains (124–129: the stranger's attacks on matches and servers).
constexpr auto kReplayedState = static_cast<Domain>(125);
constexpr auto kReplayFlood = static_cast<Domain>(128);
constexpr auto kReplayedResult = static_cast<Domain>(129);

class ReplayedStateTest : public ClientIntegrationTest {};

/// The stranger: keeps every MatchState it reads, in every match's partition, and writes any of
/// them back as it was (signature and all).
class StateReplayer {
 public:
  explicit StateReplayer(std::uint32_t domain)
      : bus_(domain),
        subscriber_(bus_.participant, pool::test::everyPartition()),
        publisher_(bus_.participant, pool::test::everyPartition()),
        reader_(subscriber_, bus_.state_topic, keepAll(net::qos::state())),
        writer_(publisher_, bus_.state_topic, keepAll(net::qos::state())) {}

  /// Keeps the first state read with `shot_number` shots played (one at most).
  void capture(std::uint32_t shot_number) {
    for (auto& sample : reader_.take()) {
      newest_ = std::max(newest_, sample->revision);
      if (!captured_ && sample->shot_number == shot_number) captured_ = std::move(sample);
    }
  }
  /// The highest revision read so far.
  std::uint32_t newest() const { return newest_; }
  const pool_MatchState* captured() const { return captured_ ? captured_->get() : nullptr; }

  /// Writes the captured state again, `times` times, once `readers` readers of the match are
  /// matched (every copy is delivered: the writer keeps all).
  bool replay(std::uint32_t readers, int times = 1) {
    if (!captured_ || !writer_.waitForReaders(readers, 30s)) return false;
    for (int i = 0; i < times; ++i) {
      if (!writer_.write(**captured_)) return false;
    }
    return true;
  }

 private:
  static net::QosProfile keepAll(net::QosProfile profile) {
    profile.history_depth = 0;
    return profile;
  }

  net::ProtocolTopics bus_;
  net::Subscriber subscriber_;
  net::Publisher publisher_;
  net::Reader<pool_MatchState> reader_;
  net::Writer<pool_MatchState> writer_;
  std::optional<net::Sample<pool_MatchState>> captured_;
  std::uint32_t newest_ = 0;
};

/// The stranger for results: keeps the first final ShotResult it reads (of an accepted shot,
/// with its verdict), in any match's partition, and writes it back as it was.
class ResultReplayer {
 public:
  explicit ResultReplayer(std::uint32_t domain)
      : bus_(domain),
        subscriber_(bus_.participant, pool::test::everyPartition()),
        publisher_(bus_.participant, pool::test::everyPartition()),
        reader_(subscriber_, bus_.result_topic, all(net::qos::result())),
        writer_(publisher_, bus_.result_topic, all(net::qos::result())) {}

  void capture() {
    for (auto& sample : reader_.take()) {
      if (!captured_ && sample->accepted && sample->verdict_text[0] != '\0') {
        captured_ = std::move(sample);
      }
    }
  }
  const pool_ShotResult* captured() const { return captured_ ? captured_->get() : nullptr; }

  bool replay(std::uint32_t readers, int times) {
    if (!captured_ || !writer_.waitForReaders(readers, 30s)) return false;
    for (int i = 0; i < times; ++i) {
      if (!writer_.write(**captured_)) return false;
    }
    return true;
  }

 private:
  static net::QosProfile all(net::QosProfile profile) {
    profile.history_depth = 0;
    return profile;
  }

  net::ProtocolTopics bus_;
  net::Subscriber subscriber_;
  net::Publisher publisher_;
  net::Reader<pool_ShotResult> reader_;
  net::Writer<pool_ShotResult> writer_;
  std::optional<net::Sample<pool_ShotResult>> captured_;
};

TEST_F(ReplayedStateTest, AnOlderGenuineStateChangesNothingAndTheMatchGoesOn) {
  open(kReplayedState, "replayed-state");
  StateReplayer stranger(kReplayedState);
  MatchRecorder recorder(kReplayedState);
  startServer({"--fast"});
  ASSERT_TRUE(recorder.pump(20s, [&] { return recorder.latest("srv-1") != nullptr; })) << logs();
  ChildProcess& alice = startBot("alice", 51, {"--think", "0.2"});
  ChildProcess& bob = startBot("bob", 52, {"--think", "0.2"});
  // The state after the break (a genuine one, signed by the server), then two more shots.
  ASSERT_TRUE(recorder.pump(60s, [&] {
    stranger.capture(1);
    const MatchView* v = recorder.latest("srv-1");
    return stalledOnLayout(recorder) ||
           (stranger.captured() && v && v->shot_number >= 3 && v->shooter >= 0);
  })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder));
  const MatchView before = *recorder.latest("srv-1");
  ASSERT_LT(stranger.captured()->revision, before.revision);

  // Replayed into the match's partition while the bots and the recorder follow it (at least four
  // readers: the recorder's two, the bots'; matched long ago, the writer was made first).
  ASSERT_TRUE(stranger.replay(4)) << logs();
  const std::string dropped = "older than the revision already taken";
  EXPECT_TRUE(recorder.pump(30s, [&] {
    return alice.err().find(dropped) != std::string::npos &&
           bob.err().find(dropped) != std::string::npos;
  })) << logs();
  EXPECT_GE(recorder.latest("srv-1")->revision, before.revision);
  EXPECT_GE(recorder.client().stale(), 1u);

  // Shots keep being accepted: two more (or the match's end).
  const bool on = recorder.pump(90s, [&] {
    const MatchView* v = recorder.latest("srv-1");
    return stalledOnLayout(recorder) || v->shot_number >= before.shot_number + 2 ||
           v->phase == MatchPhase::Over;
  });
  ASSERT_FALSE(stalledOnLayout(recorder));
  EXPECT_TRUE(on) << "the match froze at shot " << recorder.latest("srv-1")->shot_number << "\n"
                  << logs();
}

TEST_F(ReplayedStateTest, ReplaysPastTheReadersDepthHideNoNewerState) {
  open(kReplayFlood, "replay-flood");
  StateReplayer stranger(kReplayFlood);
  MatchRecorder recorder(kReplayFlood);
  startServer({"--fast"});
  ASSERT_TRUE(recorder.pump(20s, [&] { return recorder.latest("srv-1") != nullptr; })) << logs();
  // Bots that think 6 s between shots: the server publishes nothing for that long at rest.
  startBot("alice", 61, {"--think", "6"});
  startBot("bob", 62, {"--think", "6"});
  // A state before the break (to replay), then the break played.
  ASSERT_TRUE(recorder.pump(60s, [&] {
    stranger.capture(0);
    const MatchView* v = recorder.latest("srv-1");
    return stalledOnLayout(recorder) ||
           (stranger.captured() && v && v->shot_number >= 1 && v->shooter >= 0);
  })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder));
  const std::uint32_t shots = recorder.latest("srv-1")->shot_number;

  // The recorder's client stops taking samples. The server's state after the next shot reaches
  // its reader (seen by the stranger, unchanged for 1 s: at rest, the bots thinking); then the
  // stranger writes the old state twice as often as the reader keeps (net::kReaderDepth), which
  // pushes the newer genuine state out of that reader's history.
  std::uint32_t genuine = 0;
  auto changed = std::chrono::steady_clock::now();
  for (const auto until = changed + 60s; std::chrono::steady_clock::now() < until;) {
    stranger.capture(0);
    if (stranger.newest() != genuine) {
      genuine = stranger.newest();
      changed = std::chrono::steady_clock::now();
    } else if (genuine > recorder.latest("srv-1")->revision &&
               std::chrono::steady_clock::now() - changed >= 1s) {
      break;
    }
    std::this_thread::sleep_for(50ms);
  }
  ASSERT_GT(genuine, recorder.latest("srv-1")->revision) << "no shot after shot " << shots;
  ASSERT_TRUE(stranger.replay(4, 2 * static_cast<int>(net::kReaderDepth))) << logs();
  std::this_thread::sleep_for(300ms);

  // The client takes the replays, drops them as older, and follows the match afresh: the
  // server's writer hands it the state it had missed, before anything newer is published.
  EXPECT_TRUE(recorder.pump(2s, [&] { return recorder.latest("srv-1")->revision >= genuine; }))
      << "the client stayed at revision " << recorder.latest("srv-1")->revision << " of " << genuine
      << "\n"
      << logs();
  stranger.capture(0);
  EXPECT_EQ(stranger.newest(), genuine) << "the server published again meanwhile: inconclusive";
  EXPECT_GE(recorder.client().stale(), 1u);
}

TEST_F(ReplayedStateTest, AGenuineResultReplayedIsTakenOnce) {
  open(kReplayedResult, "replayed-result");
  ResultReplayer stranger(kReplayedResult);
  MatchRecorder recorder(kReplayedResult);
  startServer({"--fast"});
  ASSERT_TRUE(recorder.pump(20s, [&] { return recorder.latest("srv-1") != nullptr; })) << logs();
  startBot("alice", 71, {"--think", "3"});
  startBot("bob", 72, {"--think", "3"});
  // The break's final result (the latest result of its seat while the bots think).
  ASSERT_TRUE(recorder.pump(60s, [&] {
    stranger.capture();
    return stalledOnLayout(recorder) || stranger.captured() != nullptr;
  })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder));
  const pool_ShotResult& final = *stranger.captured();
  const auto copies = [&] {
    std::size_t n = 0;
    for (const ShotReport& r : recorder.reports()) {
      n += r.seat == final.seat && r.seq == final.seq && r.shot_number == final.shot_number &&
                   r.final()
               ? 1
               : 0;
    }
    return n;
  };
  ASSERT_TRUE(recorder.pump(10s, [&] { return copies() == 1; })) << logs();
  const std::uint64_t stale = recorder.client().stale();

  // Written back three times into the match's partition (once the recorder's and the bots'
  // readers are matched): the recorder drops each copy, and its record keeps the one.
  ASSERT_TRUE(stranger.replay(3, 3)) << logs();
  EXPECT_TRUE(recorder.pump(5s, [&] { return recorder.client().stale() >= stale + 3; }))
      << "stale " << recorder.client().stale() << " of " << stale + 3;
  EXPECT_EQ(copies(), 1u);
}

}  // namespace
}  // namespace pool::client::test
