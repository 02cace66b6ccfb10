// pool-web against a flood of connections from one address: 256 WebSockets that never read, 400
// idle TCP connections and 330 slow requests from 127.0.0.2 never lock out a browser from
// another address, and the idle and slow ones are closed once their timeouts pass while the
// browser that reads stays.
#include <gtest/gtest.h>

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/client_fixture.h"
#include "support/web_process.h"

namespace pool::client::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class ConnectionFloodTest : public ClientIntegrationTest {};

using Browser = websocket::stream<tcp::socket>;

/// A WebSocket from `source`, its handshake done; nothing read yet.
std::unique_ptr<Browser> openBrowser(asio::io_context& io, const std::string& source,
                                     std::uint16_t port, beast::error_code& ec) {
  auto ws = std::make_unique<Browser>(connectFrom(io, source, port));
  ws->handshake("127.0.0.1", "/ws", ec);
  return ws;
}

TEST_F(ConnectionFloodTest, IdleAndSlowConnectionsFromOneAddressNeverLockOutABrowser) {
  open(kWebConnectionFlood, "web-connection-flood");
  // The default slots (256 browsers, 64 HTTP connections) and short timeouts: a silent
  // WebSocket is pinged after 0.5 s and closed after 1 s, a request must arrive within 1 s.
  ChildProcess& web =
      start("pool-web", webArgs(domain_, {"--http-timeout", "1", "--idle-timeout", "1"}), "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();
  asio::io_context io;
  const std::string attacker = "127.0.0.2";

  // The flood: every browser slot taken by WebSockets that never read, then 400 more TCP
  // connections, 330 of them starting a request they never finish.
  const auto flood_from = std::chrono::steady_clock::now();
  std::vector<std::unique_ptr<Browser>> idle;
  for (int i = 0; i < 256; ++i) {
    beast::error_code ec;
    idle.push_back(openBrowser(io, attacker, port, ec));
    ASSERT_FALSE(ec) << "flood browser " << i << ": " << ec.message();
  }
  std::vector<tcp::socket> pending;
  for (int i = 0; i < 400; ++i) {
    pending.push_back(connectFrom(io, attacker, port));
    if (i < 330) {
      const std::string start = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n";
      ::send(pending.back().native_handle(), start.data(), start.size(), MSG_NOSIGNAL);
    }
  }
  // The flooding address gets no more: its new connection is closed unanswered (its share of
  // the HTTP connections is full: the end of the stream, or a reset when its request was not
  // read) or, once through, its upgrade is answered 503.
  beast::error_code refused;
  openBrowser(io, attacker, port, refused);
  EXPECT_TRUE(refused == websocket::error::upgrade_declined ||
              refused == http::error::end_of_stream || refused == asio::error::connection_reset)
      << "the flooding address got a 257th browser: " << refused.message();

  // A browser from another address gets the page and a WebSocket at once, and its lobby.
  {
    auto socket = connectFrom(io, "127.0.0.1", port);
    http::request<http::empty_body> request(http::verb::get, "/", 11);
    request.set(http::field::host, "127.0.0.1");
    http::write(socket, request);
    beast::flat_buffer buffer;
    http::response<http::string_body> page;
    http::read(socket, buffer, page);
    EXPECT_EQ(page.result(), http::status::ok);
  }
  beast::error_code ec;
  auto reader = openBrowser(io, "127.0.0.1", port, ec);
  ASSERT_FALSE(ec) << "the other address's browser was refused: " << ec.message();
  beast::flat_buffer buffer;
  reader->read(buffer, ec);
  ASSERT_FALSE(ec) << ec.message();
  EXPECT_EQ(nlohmann::json::parse(beast::buffers_to_string(buffer.data()))["type"], "lobby");
  const double served_after =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - flood_from).count();

  // The browser goes on reading (answering pings as a browser does) while the flood's timeouts
  // pass: three idle timeouts.
  ReadingBrowser reading(*reader);
  std::this_thread::sleep_for(std::chrono::seconds(3));
  EXPECT_FALSE(reading.closed()) << "the browser that reads was closed\n" << web.err();

  int idle_open = 0, pending_open = 0;
  for (auto& ws : idle) idle_open += closedByPeer(ws->next_layer()) ? 0 : 1;
  for (auto& socket : pending) pending_open += closedByPeer(socket) ? 0 : 1;
  EXPECT_EQ(idle_open, 0) << "WebSockets that never read still open after 3 idle timeouts";
  EXPECT_EQ(pending_open, 0) << "idle or slow HTTP connections still open after 3 timeouts";

  // With the flood gone, the flooding address is served again.
  auto again = openBrowser(io, attacker, port, ec);
  EXPECT_FALSE(ec) << "the flooding address is still refused: " << ec.message();
  std::printf("a browser of another address was served %.2f s into the flood\n", served_after);
}

}  // namespace
}  // namespace pool::client::test
