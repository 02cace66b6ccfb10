// A stranger tries to make a seated player lose by forfeit: it disposes the JoinRequest instance
// and floods spectate requests under her client id while she stalls; she rejoins and the match
// ends by play.
#include <gtest/gtest.h>

#include <csignal>
#include <thread>

#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "support/client_fixture.h"
#include "support/spectate_request.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

/// This test's DDS domain (124–127: the stranger's attacks on matches and servers).
constexpr auto kForcedForfeit = static_cast<Domain>(124);

class ForcedForfeitTest : public ClientIntegrationTest {};

/// The stranger: reads the players' join requests off the wire and writes its own, from a
/// participant of its own.
class Stranger {
 public:
  explicit Stranger(std::uint32_t domain)
      : bus_(domain),
        requests_(bus_.participant, bus_.join_request_topic, net::qos::joinRequest()),
        replies_(bus_.participant, bus_.join_reply_topic, net::qos::joinReply()),
        writer_(bus_.participant, bus_.join_request_topic, net::qos::joinRequest()) {}

  /// The client id that player `name` asks for a seat under, once read (empty before).
  std::string clientOf(const std::string& name) {
    for (auto& sample : requests_.take()) {
      if (net::textOf(sample->name) == name) client_ = std::string(net::textOf(sample->client));
    }
    return client_;
  }

  /// Disposes the JoinRequest instance with `client`'s id in it, as if a writer of hers had, and
  /// lets go of it. (JoinRequest has no key since protocol 6: there is one instance, which every
  /// client's requests share; before, this was her instance alone.)
  bool dispose(const std::string& client) {
    pool_JoinRequest key{};
    net::setText(key.client, client);
    return writer_.dispose(key) && writer_.unregister(key);
  }

  /// Asks to watch `match` under a client id of the stranger's own and waits for the answer: the
  /// server has then read everything this writer wrote before.
  bool answeredAfter(const std::string& match, std::chrono::seconds timeout) {
    if (!writer_.write(*pool::test::spectateRequest("stranger-probe", match, 1))) return false;
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      for (auto& reply : replies_.take()) {
        if (net::textOf(reply->client) == "stranger-probe") return true;
      }
      std::this_thread::sleep_for(20ms);
    }
    return false;
  }

  /// Asks to watch `match` under `client`'s id, `per_second` times a second, until `stop`.
  void flood(const std::string& client, const std::string& match, double per_second,
             const std::atomic<bool>& stop) {
    const auto t0 = std::chrono::steady_clock::now();
    for (std::uint32_t i = 0; !stop.load(); ++i) {
      std::this_thread::sleep_until(t0 + std::chrono::duration<double>(i / per_second));
      // Numbers of its own: this is about limits, not replies.
      const auto w = pool::test::spectateRequest(client, match, 1000000 + i);
      if (writer_.write(*w)) ++sent_;
      (void)writer_.unregister(*w);  // and lets go of the instance again, as the disposal did
    }
  }

  std::uint64_t sent() const { return sent_.load(); }

 private:
  net::ProtocolTopics bus_;
  net::Reader<pool_JoinRequest> requests_;
  net::Reader<pool_JoinReply> replies_;
  net::Writer<pool_JoinRequest> writer_;
  std::string client_;
  std::atomic<std::uint64_t> sent_{0};
};

TEST_F(ForcedForfeitTest, ADisposalAndAFloodUnderHerIdDoNotTakeHerSeat) {
  open(kForcedForfeit, "forced-forfeit");
  Stranger stranger(kForcedForfeit);  // reads the join requests from the start
  MatchRecorder recorder(kForcedForfeit);
  // A short grace: a rejoin the flood held off would lose the match well within the test.
  ChildProcess& server = startServer({"--fast", "--grace", "10"});
  ASSERT_TRUE(recorder.pump(20s, [&] { return recorder.latest("srv-1") != nullptr; })) << logs();
  ChildProcess& alice = startBot("alice", 41, {"--think", "0.2"});
  ChildProcess& bob = startBot("bob", 42, {"--think", "0.2"});
  std::string victim;
  ASSERT_TRUE(recorder.pump(30s, [&] {
    victim = stranger.clientOf("alice");
    const MatchView* v = recorder.latest("srv-1");
    return stalledOnLayout(recorder) || (!victim.empty() && v && v->shot_number >= 1);
  })) << logs();
  ASSERT_FALSE(stalledOnLayout(recorder));

  // The instance her requests travel in, disposed by someone else: nothing happens. Once the
  // server has answered the stranger's next request it has read the disposal too, and she is
  // still there.
  ASSERT_TRUE(stranger.dispose(victim));
  ASSERT_TRUE(stranger.answeredAfter("srv-1", 20s)) << "the server never answered\n" << logs();
  recorder.pump(200ms);
  {
    const MatchView* v = recorder.latest("srv-1");
    ASSERT_NE(v, nullptr);
    const int seat = seatOf(*v, "alice");
    ASSERT_GE(seat, 0);
    EXPECT_TRUE(v->seats[static_cast<std::size_t>(seat)].connected) << "the disposal took her away";
  }
  EXPECT_EQ(server.err().find("client " + victim + " is gone"), std::string::npos) << server.err();
  // Then spectate requests under her id, 3000 a second, while she stalls past her lease (5 s; at
  // most her participant's, 10 s, after the disposal) and shows away, and comes back: her rejoin
  // must get through.
  alice.kill(SIGSTOP);
  std::atomic<bool> stop{false};
  std::thread flood([&] { stranger.flood(victim, "srv-1", 3000.0, stop); });
  const bool away = recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest("srv-1");
    const int seat = v ? seatOf(*v, "alice") : -1;
    return seat >= 0 && !v->seats[static_cast<std::size_t>(seat)].connected;
  });
  recorder.pump(1s);
  alice.kill(SIGCONT);
  const bool back = away && recorder.pump(20s, [&] {
    return server.err().find("join rejoin srv-1 by " + victim) != std::string::npos;
  });
  recorder.pump(1s);  // the flood goes on a little after her rejoin
  stop = true;
  flood.join();
  ASSERT_TRUE(away) << logs();
  ASSERT_TRUE(back) << logs();
  std::printf("%llu spectate requests under alice's client id\n",
              static_cast<unsigned long long>(stranger.sent()));
  EXPECT_EQ(server.err().find("(disposed)"), std::string::npos) << server.err();
  // Her going is told once, though the stranger's writes let go of her instance thousands of times.
  std::size_t told = 0;
  const std::string log = server.err(), gone = "client " + victim + " is gone";
  for (auto at = log.find(gone); at != std::string::npos; at = log.find(gone, at + 1)) ++told;
  EXPECT_LE(told, 2u) << "her going logged " << told << " times";
  EXPECT_EQ(server.err().find("join rejoin srv-1 by " + victim + " (alice): accepted"),
            server.err().find("join rejoin srv-1 by " + victim))
      << server.err();

  // The match ends as it is played, not by forfeit.
  const bool ended = recorder.pump(
      120s, [&] { return stalledOnLayout(recorder) || (!alice.running() && !bob.running()); });
  ASSERT_FALSE(stalledOnLayout(recorder));
  ASSERT_TRUE(ended) << logs();
  EXPECT_EQ(alice.waitExit(1s), 0) << alice.err();
  EXPECT_EQ(bob.waitExit(1s), 0) << bob.err();
  recorder.pump(5s, [&] { return recorder.latest("srv-1")->phase == MatchPhase::Over; });
  const MatchView* final_state = recorder.latest("srv-1");
  ASSERT_EQ(final_state->phase, MatchPhase::Over);
  EXPECT_NE(final_state->end, rules::GameEnd::Forfeit) << final_state->last_verdict;
}

}  // namespace
}  // namespace pool::client::test
