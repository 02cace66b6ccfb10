// pool-web against 1 100 made-up server ids, each entry signed by a key of its own (pinned at
// first sight): a server started after them is still seen, a server known before keeps its key
// (an entry under its id signed by another key is dropped), and a browser that reads stays.
#include <gtest/gtest.h>

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
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

class PinFloodTest : public ClientIntegrationTest {};

TEST_F(PinFloodTest, ANewServerIsSeenPastAThousandMadeUpIdsAndAKnownOneKeepsItsKey) {
  open(kWebPinFlood, "web-pin-flood");
  startServer({});
  ChildProcess& web = start("pool-web", webArgs(domain_, {"--stats", "0.2"}), "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();

  // A browser that reads throughout; the matches of the last lobby it heard.
  asio::io_context io;
  websocket::stream<tcp::socket> reader(connectFrom(io, "127.0.0.1", port));
  reader.handshake("127.0.0.1", "/ws");
  std::mutex mutex;
  std::set<std::string> matches;
  ReadingBrowser reading(reader, [&](const std::string& text) {
    const auto message = nlohmann::json::parse(text);
    if (message["type"] != "lobby") return;
    std::set<std::string> now;
    for (const auto& entry : message["matches"]) now.insert(entry["match"].get<std::string>());
    const std::lock_guard<std::mutex> lock(mutex);
    matches = std::move(now);
  });
  const auto lobby = [&] {
    const std::lock_guard<std::mutex> lock(mutex);
    return matches;
  };
  ASSERT_TRUE(pollUntil([&] { return lobby().count("srv-1") != 0; }, std::chrono::seconds(20)))
      << logs();

  // The flood: 1 100 server ids, each with a key of its own and one lobby entry.
  pool::test::Forger forger(domain_);
  for (int i = 0; i < 1100; ++i) {
    forger.signWith(protocol::generateKeyPair());
    const std::string id = "made-up" + std::to_string(i);
    ASSERT_TRUE(forger.publishInfo(id, id + "-1")) << i;
  }
  ASSERT_TRUE(pollUntil([&] { return lobby().size() >= 1101; }, std::chrono::seconds(20)))
      << "the flood's entries never all reached the browser: " << lobby().size();
  // An entry under the known server's id, signed by yet another key.
  forger.signWith(protocol::generateKeyPair());
  ASSERT_TRUE(forger.publishInfo("srv", "srv-9"));

  // A server started now is seen.
  start("pool-server",
        {"--domain", std::to_string(domain_), "--tables", "1", "--server-id", "late", "--db",
         file("late.db")},
        "late");
  EXPECT_TRUE(pollUntil([&] { return lobby().count("late-1") != 0; }, std::chrono::seconds(20)))
      << "the server started after the flood is not in the lobby\n"
      << web.err().substr(0, 4000);
  const auto seen = lobby();
  EXPECT_EQ(seen.count("srv-1"), 1u);
  EXPECT_EQ(seen.count("srv-9"), 0u) << "an entry under a known id signed by another key was taken";
  EXPECT_FALSE(reading.closed()) << "the browser that reads was dropped";
  std::printf("lobby after the flood: %zu matches\n", seen.size());
}

}  // namespace
}  // namespace pool::client::test
