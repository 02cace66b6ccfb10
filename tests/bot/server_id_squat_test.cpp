// A stranger holds a server's id in the lobby (an entry forged with a key of its own, an unsigned
// one, and the server's own genuine entry captured earlier and written again, all kept by a
// transient-local writer): the server restarts past them at once and serves on.
#include <gtest/gtest.h>

#include <csignal>
#include <optional>

#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/sample.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "support/client_fixture.h"
#include "support/forger.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

/// This test's DDS domain (124–127: the stranger's attacks on matches and servers).
constexpr auto kServerIdSquat = static_cast<Domain>(126);

class ServerIdSquatTest : public ClientIntegrationTest {};

/// Keeps the first lobby entry of a server id it reads, and writes it again as it was.
class EntryReplayer {
 public:
  explicit EntryReplayer(std::uint32_t domain)
      : bus_(domain),
        reader_(bus_.participant, bus_.match_info_topic, net::qos::lobby()),
        writer_(bus_.participant, bus_.match_info_topic, net::qos::lobby()) {}

  bool capture(const std::string& server) {
    for (auto& sample : reader_.take()) {
      if (!captured_ && net::textOf(sample->server) == server) captured_ = std::move(sample);
    }
    return captured_.has_value();
  }

  bool replay() { return captured_ && static_cast<bool>(writer_.write(**captured_)); }

 private:
  net::ProtocolTopics bus_;
  net::Reader<pool_MatchInfo> reader_;
  net::Writer<pool_MatchInfo> writer_;
  std::optional<net::Sample<pool_MatchInfo>> captured_;
};

/// Polls `recorder` until `done()` or `timeout`.
bool waitFor(MatchRecorder& recorder, const std::function<bool()>& done, std::chrono::seconds t) {
  return recorder.pump(t, done);
}

TEST_F(ServerIdSquatTest, AServerRestartsPastForgedAndReplayedEntriesOfItsId) {
  open(kServerIdSquat, "id-squat");
  EntryReplayer replayer(kServerIdSquat);
  MatchRecorder recorder(kServerIdSquat);
  {
    ChildProcess& first = startServer({"--fast", "--db", file("a.db")});
    ASSERT_TRUE(waitFor(
        recorder, [&] { return replayer.capture("srv"); }, 20s))
        << logs();
    first.kill(SIGTERM);
    ASSERT_EQ(first.waitExit(20s), 0) << first.err();
  }

  // The stranger's entries under "srv": one signed by a key of its own, one unsigned, and the
  // server's genuine one written again; its writers stay (transient-local: a late reader gets
  // them).
  pool::test::Forger forger(kServerIdSquat);
  forger.signWith(protocol::generateKeyPair());
  ASSERT_TRUE(forger.publishInfo("srv", "srv-7"));
  forger.signWith(std::nullopt);
  ASSERT_TRUE(forger.publishInfo("srv", "srv-8"));
  ASSERT_TRUE(replayer.replay());

  const auto restarted = std::chrono::steady_clock::now();
  ChildProcess& again = startServer({"--fast", "--db", file("a.db")});
  ASSERT_TRUE(waitFor(
      recorder,
      [&] {
        return !again.running() || again.err().find("server srv on domain") != std::string::npos;
      },
      30s))
      << again.err();
  std::printf("restarted past the stranger's entries: serving after %.2f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - restarted).count());
  ASSERT_TRUE(again.running()) << again.err();
  EXPECT_NE(again.err().find("is not this database's"), std::string::npos) << again.err();
  EXPECT_NE(again.err().find("is still seen"), std::string::npos) << again.err();
  // Nobody with its key answers its challenge: it serves on past the window.
  EXPECT_TRUE(waitFor(
      recorder,
      [&] {
        return !again.running() ||
               again.err().find("no other server with this database's key answered") !=
                   std::string::npos;
      },
      60s))
      << again.err();
  EXPECT_TRUE(again.running()) << again.err();
  again.kill(SIGTERM);
  EXPECT_EQ(again.waitExit(20s), 0) << again.err();
}

}  // namespace
}  // namespace pool::client::test
