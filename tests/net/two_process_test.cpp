// Two real processes over loopback DDS: a forked peer plays a player, this process the server.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "net/convert.h"
#include "net/topic.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "net_fixture.h"

namespace pool::net {
namespace {

using namespace protocol;

using namespace test;

constexpr std::uint32_t kCommands = 200;
constexpr auto kPeerLease = std::chrono::milliseconds(300);

/// The player's side, in the forked and re-executed peer: announces a match, sends kCommands
/// ShotCommands (or one, then hangs when `hang`), then waits for the server's ShotResult.
int runPeer(std::uint32_t domain, bool hang) {
  Participant p(domain);
  Topic<pool_MatchInfo> info_topic(p);
  Topic<pool_ShotCommand> command_topic(p);
  Topic<pool_ShotResult> result_topic(p);
  Writer<pool_MatchInfo> info_writer(p, info_topic, qos::lobby());
  Writer<pool_ShotCommand> commands(p, command_topic, qos::command(kPeerLease));
  Reader<pool_ShotResult> results(p, result_topic, qos::result());
  pool_MatchInfo info{};
  setText(info.match, "peer-1");
  setText(info.server, "peer");
  info.protocol_version = kProtocolVersion;
  if (!info_writer.write(info) || !commands.waitForReaders(1, std::chrono::seconds(10))) return 3;
  const std::uint32_t count = hang ? 1 : kCommands;
  for (std::uint32_t seq = 1; seq <= count; ++seq) {
    ShotRequest r;
    r.match = "peer-1";
    r.seq = seq;
    r.cue.speed = 1.0 + seq * 0.01;
    if (!commands.write(*toWire(r))) return 4;
  }
  if (hang) {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // until killed
  }
  const auto got = takeAtLeast(p, results, 1, std::chrono::seconds(10));
  return got.size() == 1 && got[0]->seq == kCommands ? 0 : 5;
}

/// When this binary is re-executed as the peer, play it before gtest starts, and exit (through
/// exit(), so a sanitizer build checks the peer for leaks too).
const bool kIsPeer = [] {
  const char* domain = std::getenv("POOL_NET_PEER_DOMAIN");
  if (!domain) return false;
  const char* mode = std::getenv("POOL_NET_PEER_MODE");
  std::_Exit(
      runPeer(static_cast<std::uint32_t>(std::atoi(domain)), mode && std::string(mode) == "hang"));
}();

/// Forks and re-executes this test binary as the peer (a fresh process: no DDS state inherited).
pid_t spawnPeer(std::uint32_t domain, const char* mode) {
  const pid_t pid = fork();
  if (pid == 0) {
    ::setenv("POOL_NET_PEER_DOMAIN", std::to_string(domain).c_str(), 1);
    ::setenv("POOL_NET_PEER_MODE", mode, 1);
    execl("/proc/self/exe", "net_tests_peer", static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  return pid;
}

/// Waits for `pid` to exit and returns its exit code (-1 if it did not exit normally).
int exitCodeOf(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class TwoProcesses : public NetTest {};

TEST_F(TwoProcesses, CommandsInOrderAndAResultBack) {
  const pid_t peer = spawnPeer(kTwoProcesses, "play");
  ASSERT_GT(peer, 0);
  Participant server(kTwoProcesses);
  Topic<pool_MatchInfo> info_topic(server);
  Topic<pool_ShotCommand> command_topic(server);
  Topic<pool_ShotResult> result_topic(server);
  Reader<pool_MatchInfo> lobby(server, info_topic, qos::lobby());
  Reader<pool_ShotCommand> commands(server, command_topic, qos::command());
  Writer<pool_ShotResult> results(server, result_topic, qos::result());

  const auto infos = takeAtLeast(server, lobby, 1, 10s);
  ASSERT_EQ(infos.size(), 1u);
  EXPECT_EQ(textOf(infos[0]->match), "peer-1");
  const auto got = takeAtLeast(server, commands, kCommands, 10s);
  ASSERT_EQ(got.size(), kCommands);
  for (std::uint32_t i = 0; i < kCommands; ++i) {
    const auto request = fromWire(*got[i]);
    ASSERT_TRUE(request) << request.error();
    ASSERT_EQ(request->seq, i + 1);
    EXPECT_EQ(request->cue.speed, 1.0 + (i + 1) * 0.01);
  }

  Sample<pool_ShotResult> result;
  setText(result->match, "peer-1");
  result->seq = kCommands;
  result->accepted = true;
  ASSERT_TRUE(results.write(*result));  // transient-local: reaches the peer even if it is late
  EXPECT_EQ(exitCodeOf(peer), 0);
}

TEST_F(TwoProcesses, AKilledPlayerLosesLivelinessOnItsWritersLease) {
  const pid_t peer = spawnPeer(kLiveliness, "hang");
  ASSERT_GT(peer, 0);
  Participant server(kLiveliness);
  Topic<pool_ShotCommand> command_topic(server);
  Reader<pool_ShotCommand> commands(server, command_topic, qos::command());
  WaitSet waitset(server);
  waitset.attachLiveliness(commands, 2);
  ASSERT_EQ(takeAtLeast(server, commands, 1, 10s).size(), 1u);
  const LivelinessStatus before = commands.livelinessChanged();
  EXPECT_EQ(before.alive, 1u);

  kill(peer, SIGKILL);
  const auto killed = std::chrono::steady_clock::now();
  EXPECT_EQ(exitCodeOf(peer), -1);
  LivelinessStatus after{};
  while (after.not_alive == 0 && std::chrono::steady_clock::now() - killed < 5s) {
    waitset.wait(100ms);
    after = commands.livelinessChanged();
  }
  const auto noticed = std::chrono::steady_clock::now() - killed;
  RecordProperty(
      "noticed_ms",
      static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(noticed).count()));
  EXPECT_EQ(after.alive, 0u);
  EXPECT_EQ(after.not_alive, 1u);
  // What shows the writer's own 300 ms lease at work is that the loss is noticed well before
  // anything else would report it: the peer's participant lease (Cyclone's default, 10 s) or never
  // (an infinite writer lease). The time itself is the machine's (two processes and Cyclone's lease
  // thread on two loaded cores, under the sanitizers): 4 s is the lease plus that margin, and still
  // under half the participant's lease.
  EXPECT_LT(noticed, 4s) << "took "
                         << std::chrono::duration_cast<std::chrono::milliseconds>(noticed).count()
                         << " ms";
  // The topic's one instance (ShotCommand has no key) reads as having no writers: its only
  // writer is gone.
  const auto notices = commands.takeWithNotices();
  ASSERT_FALSE(notices.empty());
  EXPECT_EQ(notices.back().meta().instance, InstanceState::NoWriters);
}

}  // namespace
}  // namespace pool::net
