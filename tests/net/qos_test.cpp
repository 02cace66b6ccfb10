// QoS profiles as docs/PROTOCOL.md needs: late joiners, keep-all order, best effort, disposal.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <thread>

#include "support/sanitizer.h"
#if POOL_UNDER_ASAN
#include <sanitizer/lsan_interface.h>
#endif

#include "net/convert.h"
#include "net/shot_command_check.h"
#include "net/topic.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "net_fixture.h"

namespace pool::net {
namespace {

using namespace protocol;

using namespace test;

class Qos : public NetTest {};

Sample<pool_MatchState> stateOf(const std::string& match, std::uint32_t revision) {
  Sample<pool_MatchState> s;
  setText(s->match, match);
  s->revision = revision;
  s->phase = pool_PHASE_OPEN;
  putBalls(s->balls, std::vector<physics::Ball>{oddBall(0), oddBall(static_cast<int>(revision))});
  return s;
}

Sample<pool_ShotCommand> commandOf(const std::string& match, int seat, std::uint32_t seq) {
  ShotRequest r;
  r.match = match;
  r.seat = seat;
  r.seq = seq;
  r.cue.speed = 2.0;
  return toWire(r);
}

TEST_F(Qos, LateJoinerGetsTheLastMatchStatePerMatch) {
  Participant server(kLateJoiner);
  Topic<pool_MatchState> topic(server);
  Writer<pool_MatchState> writer(server, topic, qos::state());
  for (std::uint32_t revision = 1; revision <= 3; ++revision) {
    for (const char* match : {"m1", "m2", "m3"}) {
      ASSERT_TRUE(writer.write(*stateOf(match, revision)));
    }
  }

  // A spectator arrives after every write.
  Participant spectator(kLateJoiner);
  Topic<pool_MatchState> spectator_topic(spectator);
  Reader<pool_MatchState> reader(spectator, spectator_topic, qos::state());
  const auto got = takeAtLeast(spectator, reader, 3);
  std::this_thread::sleep_for(100ms);  // nothing more may come
  EXPECT_TRUE(reader.take().empty());
  ASSERT_EQ(got.size(), 3u);
  std::map<std::string, std::uint32_t> revisions;
  for (const auto& s : got) {
    revisions[std::string(textOf(s->match))] = s->revision;
    const auto balls = getBalls(s->balls);
    ASSERT_TRUE(balls) << balls.error();
    EXPECT_EQ(balls->at(1).id, 3);
  }
  EXPECT_EQ(revisions, (std::map<std::string, std::uint32_t>{{"m1", 3}, {"m2", 3}, {"m3", 3}}));
}

TEST_F(Qos, KeepAllReliableDeliversAThousandCommandsInOrder) {
  Participant server(kKeepAll);
  Participant player(kKeepAll);
  Topic<pool_ShotCommand> server_topic(server);
  Topic<pool_ShotCommand> player_topic(player);
  Reader<pool_ShotCommand> reader(server, server_topic, qos::command());
  Writer<pool_ShotCommand> writer(player, player_topic, qos::command());
  ASSERT_TRUE(writer.waitForReaders(1, 5s));
  ASSERT_TRUE(reader.waitForWriters(1, 5s));

  constexpr std::uint32_t kCount = 1000;
  for (std::uint32_t seq = 1; seq <= kCount; ++seq) {
    const Status status = writer.write(*commandOf("m1", 0, seq));  // one instance: match + seat
    ASSERT_TRUE(status) << status.error;
  }
  const auto got = takeAtLeast(server, reader, kCount, 10s);
  ASSERT_EQ(got.size(), kCount);
  for (std::uint32_t i = 0; i < kCount; ++i) {
    ASSERT_EQ(got[i]->seq, i + 1) << "at " << i;
  }
}

TEST_F(Qos, BestEffortSnapshotsArriveLatestLast) {
  Participant server(kBestEffort);
  Participant client(kBestEffort);
  Topic<pool_TableSnapshot> server_topic(server);
  Topic<pool_TableSnapshot> client_topic(client);
  Reader<pool_TableSnapshot> reader(client, client_topic, qos::snapshot());
  Writer<pool_TableSnapshot> writer(server, server_topic, qos::snapshot());
  ASSERT_TRUE(writer.waitForReaders(1, 5s));
  ASSERT_TRUE(reader.waitForWriters(1, 5s));

  constexpr std::uint32_t kFrames = 120;
  std::vector<std::uint32_t> frames;
  for (std::uint32_t frame = 0; frame < kFrames; ++frame) {
    Sample<pool_TableSnapshot> s;
    setText(s->match, "m1");
    s->frame = frame;
    s->sim_time = frame / 60.0;
    putBalls(s->balls, std::vector<physics::Ball>(16, oddBall(1)));
    ASSERT_TRUE(writer.write(*s));
    if (frame % 10 == 9) {  // a client polling now and then sees only the latest (keep-last 1)
      std::this_thread::sleep_for(2ms);
      for (const auto& got : reader.take()) frames.push_back(got->frame);
    }
  }
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(std::is_sorted(frames.begin(), frames.end()));
  EXPECT_LE(frames.size(), kFrames / 10);  // keep-last 1: at most one per poll
  EXPECT_EQ(frames.back(), kFrames - 1);
}

TEST_F(Qos, DisposedMatchReachesReadersAsANoticeWithItsKey) {
  Participant server(kDispose);
  Participant client(kDispose);
  Topic<pool_MatchInfo> server_topic(server);
  Topic<pool_MatchInfo> client_topic(client);
  Reader<pool_MatchInfo> reader(client, client_topic, qos::lobby());
  Writer<pool_MatchInfo> writer(server, server_topic, qos::lobby());
  ASSERT_TRUE(writer.waitForReaders(1, 5s));
  pool_MatchInfo info{};
  for (const char* match : {"m1", "m2"}) {
    setText(info.match, match);
    ASSERT_TRUE(writer.write(info));
  }
  ASSERT_EQ(takeAtLeast(client, reader, 2).size(), 2u);

  setText(info.match, "m1");
  ASSERT_TRUE(writer.dispose(info));
  WaitSet waitset(client);
  waitset.attachData(reader, 7);
  ASSERT_EQ(waitset.wait(5s), std::vector<std::int64_t>{7});
  const auto notices = reader.takeWithNotices();
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_FALSE(notices[0].meta().valid);
  EXPECT_EQ(notices[0].meta().instance, InstanceState::Disposed);
  EXPECT_EQ(textOf(notices[0]->match), "m1");

  // A late lobby reader sees only the match still open.
  Participant late(kDispose);
  Topic<pool_MatchInfo> late_topic(late);
  Reader<pool_MatchInfo> late_reader(late, late_topic, qos::lobby());
  const auto open = takeAtLeast(late, late_reader, 1);
  std::this_thread::sleep_for(100ms);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_EQ(textOf(open[0]->match), "m2");
  EXPECT_TRUE(late_reader.take().empty());
}

TEST_F(Qos, JoinReplyWrittenBeforeTheClientReaderExistsStillArrives) {
  Participant server(kLateReply);
  Topic<pool_JoinReply> server_topic(server);
  Writer<pool_JoinReply> writer(server, server_topic, qos::joinReply());
  pool_JoinReply reply{};
  setText(reply.client, "client-9");
  reply.outcome = pool_JOIN_ACCEPTED;
  reply.seat_token = 42;
  ASSERT_TRUE(writer.write(reply));

  Participant client(kLateReply);
  Topic<pool_JoinReply> client_topic(client);
  Reader<pool_JoinReply> reader(client, client_topic, qos::joinReply());
  const auto got = takeAtLeast(client, reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0]->seat_token, 42u);
}

TEST_F(Qos, ReadKeepsTheLatestStateForTheNextRead) {
  Participant server(kReadCache);
  Participant client(kReadCache);
  Topic<pool_MatchState> server_topic(server);
  Topic<pool_MatchState> client_topic(client);
  Reader<pool_MatchState> reader(client, client_topic, qos::state());
  Writer<pool_MatchState> writer(server, server_topic, qos::state());
  ASSERT_TRUE(writer.waitForReaders(1, 5s));
  ASSERT_TRUE(writer.write(*stateOf("m1", 1)));
  ASSERT_TRUE(writer.write(*stateOf("m1", 2)));
  WaitSet waitset(client);
  waitset.attachData(reader, 1);
  std::vector<Sample<pool_MatchState>> first;
  for (int i = 0; i < 100 && (first.empty() || first[0]->revision != 2); ++i) {
    waitset.wait(50ms);
    first = reader.read();
  }
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0]->revision, 2u);
  // Read samples stay, and no longer wake the waitset.
  EXPECT_TRUE(waitset.wait(20ms).empty());
  const auto again = reader.read();
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0]->revision, 2u);
}

TEST_F(Qos, TakeEachVisitsLoanedSamplesWithoutCopying) {
  Participant server(kTakeEach);
  Participant client(kTakeEach);
  Topic<pool_TableSnapshot> server_topic(server);
  Topic<pool_TableSnapshot> client_topic(client);
  QosProfile reliable_history = qos::snapshot();  // reliable, keep 100, to count exactly
  reliable_history.reliability = Reliability::Reliable;
  reliable_history.history_depth = 100;
  Reader<pool_TableSnapshot> reader(client, client_topic, reliable_history);
  Writer<pool_TableSnapshot> writer(server, server_topic, reliable_history);
  ASSERT_TRUE(writer.waitForReaders(1, 5s));
  for (std::uint32_t frame = 0; frame < 100; ++frame) {
    Sample<pool_TableSnapshot> s;
    setText(s->match, "m1");
    s->frame = frame;
    putBalls(s->balls, std::vector<physics::Ball>(16, oddBall(2)));
    ASSERT_TRUE(writer.write(*s));
  }
  WaitSet waitset(client);
  waitset.attachData(reader, 1);
  std::uint32_t next = 0;
  std::size_t balls = 0;
  for (int i = 0; i < 100 && next < 100; ++i) {
    waitset.wait(50ms);
    reader.takeEach([&](const pool_TableSnapshot& s, const SampleMeta& meta) {
      EXPECT_TRUE(meta.valid);
      EXPECT_EQ(s.frame, next++);
      balls += s.balls._length;
    });
  }
  EXPECT_EQ(next, 100u);
  EXPECT_EQ(balls, 1600u);
}

TEST_F(Qos, WaitSetTimesOutAndWakesOnAGuard) {
  Participant participant(kWaitSetGuard);
  GuardCondition guard(participant);
  WaitSet waitset(participant);
  waitset.attach(guard, 5);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(waitset.wait(50ms).empty());
  EXPECT_GE(std::chrono::steady_clock::now() - start, 45ms);

  std::thread waker([&] {
    std::this_thread::sleep_for(20ms);
    guard.trigger();
  });
  EXPECT_EQ(waitset.wait(5s), std::vector<std::int64_t>{5});
  waker.join();
  guard.reset();
  EXPECT_TRUE(waitset.wait(1ms).empty());
}

TEST_F(Qos, MalformedCommandCrossesTheWireAndIsDetected) {
  Participant server(kMalformedOnWire);
  Participant player(kMalformedOnWire);
  Topic<pool_ShotCommand> server_topic(server);
  Topic<pool_ShotCommand> player_topic(player);
  Reader<pool_ShotCommand> reader(server, server_topic, qos::command());
  Writer<pool_ShotCommand> writer(player, player_topic, qos::command());
  ASSERT_TRUE(writer.waitForReaders(1, 5s));
  auto nan_yaw = commandOf("m1", 0, 1);
  nan_yaw->yaw = std::numeric_limits<double>::quiet_NaN();
  auto too_fast = commandOf("m1", 0, 2);
  too_fast->speed = 50.0;
  auto bad_seat = commandOf("m1", 7, 3);
  ASSERT_TRUE(writer.write(*nan_yaw));
  ASSERT_TRUE(writer.write(*too_fast));
  ASSERT_TRUE(writer.write(*bad_seat));

  // An enum value outside the IDL's enumerators: the writer refuses to serialize it. Cyclone
  // 0.10.2 leaks the refused sample's serialization buffer (upstream issue 1540, fixed later), so
  // leak checking is off for this one write; senders validate before writing.
  auto bad_option = commandOf("m1", 0, 4);
  setRawValue(bad_option->option, 99);
  {
#if POOL_UNDER_ASAN
    __lsan::ScopedDisabler known_upstream_leak;
#endif
    const Status refused = writer.write(*bad_option);
    EXPECT_FALSE(refused);
    EXPECT_EQ(refused.error, "write: Bad Parameter");
  }

  const auto got = takeAtLeast(server, reader, 3);
  ASSERT_EQ(got.size(), 3u);
  std::map<std::uint32_t, CommandProblem> problems;
  for (const auto& s : got) problems[s->seq] = validateShotCommand(*s).code();
  EXPECT_EQ(problems[1], CommandProblem::NonFinite);
  EXPECT_EQ(problems[2], CommandProblem::SpeedOutOfRange);
  EXPECT_EQ(problems[3], CommandProblem::BadSeat);
}

}  // namespace
}  // namespace pool::net
