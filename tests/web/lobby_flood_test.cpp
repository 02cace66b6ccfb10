// pool-web against a flood of validly signed lobby entries under a new server id: the lobby it
// serves stays bounded (per server id and in bytes, the flooding id cut first), a browser that
// reads keeps its connection through the flood, one connecting afterwards gets the lobby with the
// real server's match in it.
#include <gtest/gtest.h>

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <mutex>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "support/client_fixture.h"
#include "support/forger.h"
#include "support/web_process.h"

namespace pool::client::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using nlohmann::json;

class LobbyFloodTest : public ClientIntegrationTest {};

/// What one lobby message holds.
struct LobbySeen {
  std::size_t bytes = 0;
  std::size_t entries = 0;
  std::size_t flood = 0;  ///< entries of the flooding server id
  bool real = false;      ///< the real server's match is in it
};

LobbySeen lobbySeen(const std::string& text) {
  LobbySeen seen;
  const json message = json::parse(text);
  seen.bytes = text.size();
  for (const auto& entry : message["matches"]) {
    ++seen.entries;
    if (entry["server"] == "flood") ++seen.flood;
    if (entry["match"] == "srv-1") seen.real = true;
  }
  return seen;
}

TEST_F(LobbyFloodTest, ABrowserThatReadsKeepsABoundedLobbyThroughAFloodOfSignedEntries) {
  open(kWebLobbyFlood, "web-lobby-flood");
  startServer({});
  // A queue of 128 KiB: the flood's 2 000 entries (about 0.5 MB of lobby) would outgrow it; the
  // lobby served takes at most a quarter of it (32 KiB), the flooding id cut first.
  constexpr std::size_t kQueue = 128 * 1024;
  ChildProcess& web =
      start("pool-web", webArgs(domain_, {"--queue-kib", "128", "--stats", "0.2"}), "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();

  // A browser that reads, from before the flood to its end.
  asio::io_context io;
  websocket::stream<tcp::socket> reader(connectFrom(io, "127.0.0.1", port));
  reader.handshake("127.0.0.1", "/ws");
  std::mutex mutex;
  std::vector<LobbySeen> lobbies;
  ReadingBrowser reading(reader, [&](const std::string& text) {
    if (text.find(R"("type":"lobby")") == std::string::npos) return;
    const std::lock_guard<std::mutex> lock(mutex);
    lobbies.push_back(lobbySeen(text));
  });
  const auto lastLobby = [&] {
    const std::lock_guard<std::mutex> lock(mutex);
    return lobbies.empty() ? LobbySeen{} : lobbies.back();
  };
  ASSERT_TRUE(pollUntil([&] { return lastLobby().real; }, std::chrono::seconds(20)))
      << "the real server's match never reached the browser\n"
      << logs();

  // The flood: 2 000 entries under a server id seen for the first time, signed by its own key
  // (pinned at first sight).
  pool::test::Forger forger(domain_);
  forger.signWith(protocol::generateKeyPair());
  const auto flood_from = std::chrono::steady_clock::now();
  for (int i = 1; i <= 2000; ++i) {
    ASSERT_TRUE(forger.publishInfo("flood", "flood-" + std::to_string(i))) << i;
  }
  const double flood_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - flood_from).count();
  // pool-web has taken all of them: 256 kept for that id, the other 1 744 refused.
  const std::regex taken("lobby 257 kept 1744 refused");
  ASSERT_TRUE(pollUntil(
      [&] {
        const std::string err = web.err();
        return std::regex_search(err, taken);
      },
      std::chrono::seconds(20)))
      << web.err().substr(0, 4000);
  // and its browsers heard the lobby as it is now (sent at most every 0.5 s).
  EXPECT_TRUE(pollUntil([&] { return lastLobby().flood > 0 && lastLobby().real; },
                        std::chrono::seconds(5)));

  // A browser connecting now gets the bounded lobby, the real server's match in it.
  websocket::stream<tcp::socket> late(connectFrom(io, "127.0.0.1", port));
  late.handshake("127.0.0.1", "/ws");
  beast::flat_buffer in;
  late.read(in);
  const LobbySeen first = lobbySeen(beast::buffers_to_string(in.data()));
  EXPECT_TRUE(first.real) << "the real server's match is missing from the lobby";
  EXPECT_LE(first.flood, 256u) << "more than 256 entries of one server id";
  EXPECT_LE(first.bytes, kQueue / 4) << "the lobby outgrew a quarter of the queue";
  EXPECT_GT(first.flood, 0u);
  EXPECT_LT(first.flood, 256u) << "the lobby was not cut to its bytes";

  EXPECT_FALSE(reading.closed()) << "the browser that reads was dropped\n" << web.err();
  std::size_t heard = 0, largest = 0;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    heard = lobbies.size();
    for (const auto& l : lobbies) largest = std::max(largest, l.bytes);
  }
  std::printf(
      "2000 entries written in %.2f s; the reading browser heard %zu lobbies (largest %zu B); "
      "a late browser's lobby: %zu entries, %zu of the flood, %zu B\n",
      flood_s, heard, largest, first.entries, first.flood, first.bytes);
}

}  // namespace
}  // namespace pool::client::test
