// A stranger disposes the lobby entry of the match a headless spectator watches: the spectator
// drops the disposal (not its server's writer) and goes on watching.
#include <gtest/gtest.h>

#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

/// This test's DDS domain (124–127: the stranger's attacks on matches and servers).
constexpr auto kForgedLobbyDisposal = static_cast<Domain>(127);

class ForgedLobbyDisposalTest : public ClientIntegrationTest {};

TEST_F(ForgedLobbyDisposalTest, TheSpectatorWatchesOnPastAForgedDisposal) {
  open(kForgedLobbyDisposal, "forged-lobby-disposal");
  MatchRecorder recorder(kForgedLobbyDisposal);
  startServer({"--fast"});
  ASSERT_TRUE(recorder.pump(20s, [&] { return recorder.latest("srv-1") != nullptr; })) << logs();
  ChildProcess& spectator = startSpectator("srv-1");
  ASSERT_TRUE(recorder.pump(30s, [&] {
    return !spectator.running() || spectator.out().find("srv-1") != std::string::npos;
  })) << logs();
  ASSERT_TRUE(spectator.running()) << logs();

  net::ProtocolTopics stranger(kForgedLobbyDisposal);
  net::Writer<pool_MatchInfo> lobby(stranger.participant, stranger.match_info_topic,
                                    net::qos::lobby());
  ASSERT_TRUE(lobby.waitForReaders(2, 30s));  // the recorder's and the spectator's
  pool_MatchInfo key{};
  net::setText(key.match, "srv-1");
  ASSERT_TRUE(lobby.dispose(key));
  ASSERT_TRUE(recorder.pump(30s, [&] {
    return !spectator.running() ||
           spectator.err().find("disposed by a writer other than its server's") !=
               std::string::npos;
  })) << logs();
  // Before, the spectator ended within a poll of the notice; a second more shows it does not.
  recorder.pump(1s);
  EXPECT_TRUE(spectator.running()) << logs();
  EXPECT_TRUE(recorder.client().lobby().lowestWithFreeSeat().has_value())
      << "the recorder's lobby still lists srv-1";
}

}  // namespace
}  // namespace pool::client::test
