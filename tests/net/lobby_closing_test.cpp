// A lobby entry and its disposal read in one take: DDS marks the entry's instance and sends no
// notice of its own, so the client learns of a closed match from the server's signed last entry.
#include <gtest/gtest.h>

#include <thread>
#include <variant>

#include "net/client_transport.h"
#include "net/qos_profiles.h"
#include "net/server_transport.h"
#include "net/topic.h"
#include "net/writer.h"
#include "net_fixture.h"
#include "protocol/key_pair.h"
#include "protocol/protocol_version.h"

namespace pool::net::test {
namespace {

class LobbyClosing : public ::testing::Test {
 protected:
  void SetUp() override { useLoopbackConfig(); }
};

/// Takes from `sentinel` until it has seen `match`'s instance disposed, at most 5 s.
bool sawDisposal(const Reader<pool_MatchInfo>& sentinel, const char* match) {
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  while (std::chrono::steady_clock::now() < deadline) {
    for (const auto& s : sentinel.takeWithNotices()) {
      if (textOf(s->match) == match && s.meta().instance == InstanceState::Disposed) return true;
    }
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

// The behaviour the client lives with (DDS 1.4, 2.2.2.5.3.8: a disposal changes the instance
// state, seen on the next sample taken; a sample with no data is only made when none is left to
// carry it). Tolerance: none, one sample.
TEST_F(LobbyClosing, ADisposalBeforeTheTakeOnlyMarksTheEntry) {
  Participant server(kDisposeBeforeTake);
  Participant client(kDisposeBeforeTake);
  Topic<pool_MatchInfo> server_topic(server);
  Topic<pool_MatchInfo> client_topic(client);
  Reader<pool_MatchInfo> reader(client, client_topic, qos::lobby());
  // The client participant hands each packet to all its readers at once: once this one has the
  // disposal, so has `reader`.
  Reader<pool_MatchInfo> sentinel(client, client_topic, qos::lobby());
  Writer<pool_MatchInfo> writer(server, server_topic, qos::lobby());
  ASSERT_TRUE(writer.waitForReaders(2, 5s));
  pool_MatchInfo info{};
  setText(info.match, "m1");
  ASSERT_TRUE(writer.write(info));
  ASSERT_TRUE(writer.dispose(info));
  ASSERT_TRUE(sawDisposal(sentinel, "m1"));
  const auto taken = reader.takeWithNotices();
  ASSERT_EQ(taken.size(), 1u);
  EXPECT_TRUE(taken[0].meta().valid);
  EXPECT_EQ(taken[0].meta().instance, InstanceState::Disposed);
}

TEST_F(LobbyClosing, TheServersClosedEntryIsTheMatchGoneEvenWithItsDisposalInTheSameTake) {
  ServerTransport server(kClosingEntry, protocol::generateKeyPair());
  ClientTransport client(kClosingEntry);
  Participant watcher(kClosingEntry);
  Topic<pool_MatchInfo> topic(watcher);
  Reader<pool_MatchInfo> sentinel(watcher, topic, qos::lobby());
  protocol::LobbyEntry entry;
  entry.match = "s-1";
  entry.server = "s";
  entry.name = "Table 1";
  entry.table = "wpa-9ft";
  entry.protocol_version = protocol::kProtocolVersion;
  ASSERT_EQ(server.publish(entry), "");
  const auto takeSome = [&] {
    std::vector<Result<LobbyEvent>> events;
    const auto deadline = std::chrono::steady_clock::now() + 5s;
    while (events.empty() && std::chrono::steady_clock::now() < deadline) {
      client.wait(50ms);
      events = client.takeLobby();
    }
    return events;
  };
  auto events = takeSome();
  ASSERT_EQ(events.size(), 1u);
  ASSERT_TRUE(events[0]) << events[0].error();
  ASSERT_TRUE(std::holds_alternative<protocol::LobbyEntry>(*events[0]));

  // What the server does when a match closes: its last entry says so, then it is disposed.
  entry.phase = protocol::MatchPhase::Closed;
  ASSERT_EQ(server.publish(entry), "");
  server.dispose("s-1");
  ASSERT_TRUE(sawDisposal(sentinel, "s-1"));
  std::this_thread::sleep_for(100ms);  // the client's participant has both too, most often
  events = takeSome();
  ASSERT_FALSE(events.empty());
  ASSERT_TRUE(events[0]) << events[0].error();
  const auto* gone = std::get_if<protocol::MatchGone>(&*events[0]);
  ASSERT_TRUE(gone) << "the closed entry came out as an entry, not as the match gone";
  EXPECT_EQ(gone->match, "s-1");
  EXPECT_TRUE(gone->disposed);
}

}  // namespace
}  // namespace pool::net::test
