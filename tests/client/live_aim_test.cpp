// The shooter's live aim over a real server and DDS: the seated shooter's signed aims reach a
// spectator in order; an aim from the other seat, signed by another key, unsigned, replayed or of
// another turn is dropped by the server (each drop logged with its reason) and never reaches the
// spectator; relays forged on the relay topic (unsigned, signed by another key) or replayed are
// dropped and counted by the viewer.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

#include "client/net/game_client.h"
#include "net/aim_convert.h"
#include "net/partition.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/writer.h"
#include "support/client_fixture.h"
#include "support/partitions.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

/// Two players seated in srv-1 and a spectator, each a GameClient of this process.
class LiveAimTest : public ClientIntegrationTest {
 protected:
  void setUp(Domain domain, const std::string& tag) {
    open(domain, tag);
    startServer({"--log-level", "debug"});
    ada_ = std::make_unique<GameClient>(ClientOptions{domain, "", "Ada", {}, {}});
    bob_ = std::make_unique<GameClient>(ClientOptions{domain, "", "Bob", {}, {}});
    eve_ = std::make_unique<GameClient>(ClientOptions{domain, "", "watcher", {}, {}});
    // Requests go out once the server is seen (a request written before it is lost).
    ASSERT_TRUE(pumpUntil([&] {
      return ada_->lobby().find("srv-1") && bob_->lobby().find("srv-1") &&
             eve_->lobby().find("srv-1");
    })) << logs();
    Reask reask;
    ASSERT_TRUE(pumpUntil([&] {
      const MatchView* v = eve_->state("srv-1");
      if (ada_->seat() && bob_->seat() && v && inPlay(v->phase) && v->shooter >= 0) return true;
      reask([&] {
        if (!ada_->seat()) ada_->requestSeat("srv-1", 0);
        if (!bob_->seat()) bob_->requestSeat("srv-1", 1);
        if (!v) eve_->requestSpectate("srv-1");
      });
      return false;
    })) << logs();
    const MatchView& v = *eve_->state("srv-1");
    shooter_ = v.shooter;
    shot_ = v.shot_number;
  }

  GameClient& shooter() { return shooter_ == 0 ? *ada_ : *bob_; }
  GameClient& other() { return shooter_ == 0 ? *bob_ : *ada_; }

  /// Polls every client until `done()` or `timeout`.
  bool pumpUntil(const std::function<bool()>& done, std::chrono::milliseconds timeout = 30s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      for (GameClient* c : {ada_.get(), bob_.get(), eve_.get()}) {
        if (!c) continue;
        for (auto& e : c->poll()) {
          if (c != eve_.get()) continue;
          if (auto* aim = std::get_if<protocol::AimSample>(&e)) seen_.push_back(*aim);
        }
      }
      if (done()) return true;
      if (std::chrono::steady_clock::now() >= deadline) return false;
      eve_->wait(10ms);
    }
  }

  /// The cue at `yaw` for this turn.
  protocol::AimSample aim(double yaw) const {
    protocol::AimSample a;
    a.shot_number = shot_;
    a.yaw = yaw;
    a.power = 0.25;
    a.cue_ball_x = -0.6;
    return a;
  }

  /// Waits until the spectator was handed the shooter's aim at `yaw`.
  bool spectatorSees(double yaw) {
    return pumpUntil([&] {
      for (const auto& a : seen_) {
        if (a.yaw == yaw) return true;
      }
      return false;
    });
  }

  /// Waits until the server's log says an aim of `seat` numbered `seq` was dropped for `why`.
  /// `resend` writes the sample again every 250 ms until then: a best-effort sample from a writer
  /// the server's reader has not discovered yet is lost on the way, as best effort may.
  bool serverDropped(int seat, std::uint32_t seq, const std::string& why,
                     const std::function<void()>& resend = {}) {
    const std::string line = "aim srv-1 seat " + std::to_string(seat) + " seq " +
                             std::to_string(seq) + ": dropped (" + why + ")";
    auto next = std::chrono::steady_clock::now() + 250ms;
    return pumpUntil([&] {
      if (resend && std::chrono::steady_clock::now() >= next) {
        resend();
        next += 250ms;
      }
      return processes_.front()->err().find(line) != std::string::npos;
    });
  }

  int shooter_ = -1;
  std::uint32_t shot_ = 0;
  std::unique_ptr<GameClient> ada_, bob_, eve_;
  std::vector<protocol::AimSample> seen_;
};

TEST_F(LiveAimTest, OnlyTheShootersSignedAimsReachTheSpectator) {
  ASSERT_NO_FATAL_FAILURE(setUp(kLiveAim, "live-aim"));
  ASSERT_TRUE(shooter().sendAim(aim(0.1)));
  ASSERT_TRUE(spectatorSees(0.1)) << logs();

  // A writer of player aims of its own, as an attacker on the domain has.
  net::ProtocolTopics bus(kLiveAim);
  net::Writer<pool_AimCommand> writer(bus.participant, bus.aim_command_topic, net::qos::aim());
  ASSERT_TRUE(writer.waitForReaders(1, 30s));
  auto forged = [&](std::uint32_t seq, const protocol::KeyPair* key, std::uint32_t shot) {
    protocol::AimSample a = aim(2.0);
    a.match = "srv-1";
    a.seat = shooter_;
    a.seat_token = shooter().seat()->token;
    a.seq = seq;
    a.shot_number = shot;
    if (key) protocol::signAim(a, *key);
    return static_cast<bool>(writer.write(*net::toAimCommand(a)));
  };

  // The other seat's player, with its own key and holding.
  ASSERT_TRUE(other().sendAim(aim(2.0)));
  EXPECT_TRUE(serverDropped(1 - shooter_, 1, "not the shooter")) << logs();
  // The shooter's seat and token, signed by another key, or not at all.
  const protocol::KeyPair stranger = protocol::generateKeyPair();
  ASSERT_TRUE(forged(100, &stranger, shot_));
  EXPECT_TRUE(serverDropped(shooter_, 100, "bad signature", [&] { forged(100, &stranger, shot_); }))
      << logs();
  ASSERT_TRUE(forged(101, nullptr, shot_));
  EXPECT_TRUE(serverDropped(shooter_, 101, "bad signature", [&] { forged(101, nullptr, shot_); }))
      << logs();
  // The shooter's own first aim again, byte for byte (Ed25519 signs deterministically).
  protocol::AimSample replay = aim(0.1);
  replay.match = "srv-1";
  replay.seat = shooter_;
  replay.seat_token = shooter().seat()->token;
  replay.seq = 1;
  protocol::signAim(replay, shooter().key());
  ASSERT_TRUE(writer.write(*net::toAimCommand(replay)));
  EXPECT_TRUE(serverDropped(shooter_, 1, "stale sequence", [&] {
    writer.write(*net::toAimCommand(replay));
  })) << logs();
  // Signed by the shooter's key, but for a turn that is not this one.
  ASSERT_TRUE(forged(102, &shooter().key(), shot_ + 1));
  EXPECT_TRUE(serverDropped(shooter_, 102, "another turn", [&] {
    forged(102, &shooter().key(), shot_ + 1);
  })) << logs();

  // The shooter aims on: the spectator gets it, and got nothing of the above.
  ASSERT_TRUE(shooter().sendAim(aim(0.3)));
  ASSERT_TRUE(spectatorSees(0.3)) << logs();
  for (const auto& a : seen_) {
    EXPECT_EQ(a.seat, shooter_);
    EXPECT_EQ(a.shot_number, shot_);
    EXPECT_TRUE(a.yaw == 0.1 || a.yaw == 0.3) << a.yaw;
  }
  EXPECT_EQ(seen_.size(), 2u);
  EXPECT_EQ(eve_->aimDropped(), 0u);
}

TEST_F(LiveAimTest, ForgedAndReplayedRelaysAreDroppedAndCountedByTheViewer) {
  ASSERT_NO_FATAL_FAILURE(setUp(kForgedAim, "forged-aim"));
  net::ProtocolTopics bus(kForgedAim);
  // The attacker records the server's genuine relay off the wire (in every match's partition)...
  const net::Subscriber listening(bus.participant, pool::test::everyPartition());
  net::Reader<pool_CueAim> recorder(listening, bus.cue_aim_topic, net::qos::aim());
  ASSERT_TRUE(shooter().sendAim(aim(0.1)));
  ASSERT_TRUE(spectatorSees(0.1)) << logs();
  std::vector<net::Sample<pool_CueAim>> recorded;
  ASSERT_TRUE(pumpUntil([&] {
    for (auto& s : recorder.take()) recorded.push_back(std::move(s));
    return !recorded.empty();
  })) << "the relay was not seen on the wire";

  // ... and writes relays of its own on the relay topic.
  const net::Publisher forging(bus.participant, pool::test::everyPartition());
  net::Writer<pool_CueAim> writer(forging, bus.cue_aim_topic, net::qos::aim());
  ASSERT_TRUE(writer.waitForReaders(2, 30s));  // the spectator's and the players' readers
  std::uint64_t dropped = eve_->aimDropped();
  auto expectDropped = [&](const char* what) {
    EXPECT_TRUE(pumpUntil([&] { return eve_->aimDropped() > dropped; })) << what << logs();
    dropped = eve_->aimDropped();
  };
  protocol::AimSample fake = aim(2.0);
  fake.match = "srv-1";
  fake.seat = shooter_;
  fake.seq = 50;
  {
    auto unsigned_relay = net::toCueAim(fake);
    ASSERT_TRUE(writer.write(*unsigned_relay));
    expectDropped("unsigned");
  }
  {
    auto other_key = net::toCueAim(fake);
    net::seal(*other_key, protocol::generateKeyPair());
    ASSERT_TRUE(writer.write(*other_key));
    expectDropped("signed by a key that is not the pinned one");
  }
  // The genuine relay again: its signature verifies, but it is not newer than what was taken.
  ASSERT_TRUE(writer.write(*recorded.front()));
  expectDropped("replayed");

  ASSERT_TRUE(shooter().sendAim(aim(0.3)));
  ASSERT_TRUE(spectatorSees(0.3)) << logs();
  EXPECT_EQ(seen_.size(), 2u) << "only the shooter's two aims were handed out";
  EXPECT_GE(eve_->unreadable(), 2u) << "the forged relays count as unreadable server samples";
}

// pool-bot shows its aim while it thinks: its cue swings onto the shot and draws back, then the
// stroke goes out with the very heading of the command it sends.
TEST_F(LiveAimTest, ABotsAimMovesWhileItThinksAndItsStrokeIsItsShot) {
  open(kBotAim, "bot-aim");
  MatchRecorder recorder(kBotAim);
  startServer({});
  eve_ = std::make_unique<GameClient>(ClientOptions{kBotAim, "", "watcher", {}, {}});
  ASSERT_TRUE(pumpUntil([&] { return eve_->lobby().find("srv-1") != nullptr; })) << logs();
  eve_->requestSpectate("srv-1");
  // Eve is watching before the bots come: a state of the table reaching her says her readers of
  // its partition have matched the server's writers. Aims sent before that never reach her (on a
  // loaded machine the whole first turn's could be lost, and the count below would say nothing
  // of the bot).
  ASSERT_TRUE(pumpUntil([&] { return eve_->state("srv-1") != nullptr; }, 60s)) << logs();
  // The bot plans within its think time, and only then swings the cue (3 s: under the sanitizers
  // beside the suite the plan took most of 1.5 s, and 13 aims went out, not 15).
  startBot("alice", 5, {"--think", "3"});
  startBot("bob", 6, {"--think", "3"});
  ASSERT_TRUE(recorder.waitForPlayers(2, 30s)) << logs();
  const protocol::AimSample* stroke = nullptr;
  ASSERT_TRUE(pumpUntil(
      [&] {
        recorder.pump(0ms);
        for (const auto& a : seen_) {
          if (a.stroke) stroke = &a;
        }
        return stroke != nullptr;
      },
      60s))
      << logs();
  const protocol::AimSample last = *stroke;
  // The aims before the stroke: that seat's, that turn's, many, at many headings.
  std::set<long> headings;
  int before = 0;
  for (const auto& a : seen_) {
    if (a.stroke) break;
    EXPECT_EQ(a.seat, last.seat);
    EXPECT_EQ(a.shot_number, last.shot_number);
    headings.insert(std::lround(a.yaw * 1000));
    ++before;
  }
  EXPECT_GE(before, 15) << "at least 0.5 s of a 3 s think swinging, at up to 30 aims a second";
  EXPECT_GE(headings.size(), 5u) << "the cue swung";
  // The stroke is the command's heading and speed's draw-back, as sent.
  ASSERT_TRUE(recorder.pump(30s, [&] {
    return recorder.nthCommand("srv-1", last.seat, 1) != nullptr;
  })) << logs();
  const protocol::ShotRequest* command = recorder.nthCommand("srv-1", last.seat, 1);
  EXPECT_NEAR(last.yaw, std::remainder(command->cue.yaw, 2 * 3.14159265358979323846), 1e-12);
  EXPECT_GT(last.power, 0.0);
  EXPECT_EQ(eve_->aimDropped(), 0u);
}

}  // namespace
}  // namespace pool::client::test
