// pool-web's HTTP side against bad and excessive requests: only the page's files are served, a
// path out of its folder, another method or an oversized request is refused, browsers past
// --max-browsers are declined (503), and a bad WebSocket request gets a reason and changes nothing.
#include <gtest/gtest.h>

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class HttpLimitsTest : public ClientIntegrationTest {
 protected:
  std::uint16_t startWeb(const std::vector<std::string>& extra) {
    std::vector<std::string> args{"--domain", std::to_string(domain_),
                                  "--port",   "0",
                                  "--root",   std::string(POOL_BIN_DIR) + "/../web"};
    args.insert(args.end(), extra.begin(), extra.end());
    ChildProcess& web = start("pool-web", args, "web");
    const std::regex url("http://127\\.0\\.0\\.1:([0-9]+)/");
    for (const auto until = std::chrono::steady_clock::now() + 20s;
         std::chrono::steady_clock::now() < until && web.running();) {
      std::smatch m;
      const std::string out = web.out();
      if (std::regex_search(out, m, url)) return static_cast<std::uint16_t>(std::stoi(m[1]));
      std::this_thread::sleep_for(20ms);
    }
    return 0;
  }

  /// One request on a fresh connection; the response (status 0 when the connection failed).
  http::response<http::string_body> request(http::verb verb, const std::string& target,
                                            const std::string& body = {},
                                            const std::string& header_value = {}) {
    tcp::socket socket(io_);
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port_));
    http::request<http::string_body> req(verb, target, 11);
    req.set(http::field::host, "127.0.0.1");
    if (!header_value.empty()) req.set("X-Filler", header_value);
    req.body() = body;
    req.prepare_payload();
    http::response<http::string_body> res;
    beast::error_code ec;
    http::write(socket, req, ec);
    beast::flat_buffer buffer;
    if (!ec) http::read(socket, buffer, res, ec);
    if (ec) res.result(0u);
    return res;
  }

  asio::io_context io_;
  std::uint16_t port_ = 0;
};

TEST_F(HttpLimitsTest, OnlyThePageIsServedAndTooManyBrowsersAreRefused) {
  open(kWebLimits, "web-limits");
  port_ = startWeb({"--max-browsers", "2"});
  ASSERT_NE(port_, 0) << logs();

  const auto page = request(http::verb::get, "/");
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_NE(page.body().find("app.js"), std::string::npos);
  EXPECT_EQ(page[http::field::content_type], "text/html; charset=utf-8");
  const auto three = request(http::verb::get, "/three.module.js?v=1");
  EXPECT_EQ(three.result(), http::status::ok);
  EXPECT_NE(three.body().find("three.core.js"), std::string::npos);

  // The meshes of assets/'s tables and hall, by name; three's loader with three by file name.
  const auto room = request(http::verb::get, "/assets/hall/room.obj");
  EXPECT_EQ(room.result(), http::status::ok);
  EXPECT_NE(room.body().find("o wainscot"), std::string::npos);
  EXPECT_EQ(request(http::verb::get, "/assets/tables/wpa-9ft.obj").result(), http::status::ok);
  EXPECT_EQ(request(http::verb::get, "/assets/hall/lamp-shade.obj").result(), http::status::ok);
  const auto loader = request(http::verb::get, "/OBJLoader.js");
  EXPECT_EQ(loader.result(), http::status::ok);
  EXPECT_NE(loader.body().find("from './three.module.js'"), std::string::npos);
  EXPECT_EQ(loader.body().find("from 'three'"), std::string::npos);

  for (const char* bad :
       {"/../../etc/passwd", "/..%2f..%2fetc%2fpasswd", "/nothing.js", "/.hidden", "//etc/passwd",
        "/web/index.html", "/assets/tables/wpa-9ft.json", "/assets/hall/../tables/wpa-9ft.obj",
        "/assets/cue/cue.obj", "/assets/hall/", "/assets//room.obj", "/assets/hall/nothing.obj",
        "/assets/cyclone-lo.xml"}) {
    EXPECT_EQ(request(http::verb::get, bad).result(), http::status::not_found) << bad;
  }
  EXPECT_EQ(request(http::verb::post, "/", "x").result(), http::status::method_not_allowed);
  // Past 4 KiB of body or 8 KiB of headers the connection is closed unanswered.
  EXPECT_EQ(request(http::verb::get, "/", std::string(8000, 'x')).result(), http::status{0});
  EXPECT_EQ(request(http::verb::get, "/", "", std::string(9000, 'x')).result(), http::status{0});

  // Two browsers are taken, the third is answered 503.
  std::vector<std::unique_ptr<websocket::stream<tcp::socket>>> browsers;
  for (int i = 0; i < 3; ++i) {
    auto ws = std::make_unique<websocket::stream<tcp::socket>>(io_);
    ws->next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port_));
    websocket::response_type answer;
    beast::error_code ec;
    ws->handshake(answer, "127.0.0.1", "/ws", ec);
    if (i < 2) {
      ASSERT_FALSE(ec) << ec.message();
      browsers.push_back(std::move(ws));
    } else {
      EXPECT_EQ(ec, websocket::error::upgrade_declined) << ec.message();
    }
  }
  // A browser's first message is the lobby; a bad request gets an error and nothing else.
  beast::flat_buffer buffer;
  browsers[0]->read(buffer);
  auto message = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
  buffer.consume(buffer.size());
  EXPECT_EQ(message["type"], "lobby");
  for (const std::string bad : {"{\"seat\":\"srv-1\"}", "{\"watch\":\"no-such-match\"}", "]["}) {
    browsers[0]->write(asio::buffer(bad));
    browsers[0]->read(buffer);
    message = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
    buffer.consume(buffer.size());
    EXPECT_EQ(message["type"], "error") << bad;
  }
  // A message past 4 KiB ends the connection.
  browsers[1]->read(buffer);  // the lobby
  buffer.consume(buffer.size());
  browsers[1]->write(asio::buffer(std::string(5000, ' ')));
  beast::error_code ec;
  browsers[1]->read(buffer, ec);
  EXPECT_TRUE(ec) << "still open after a message too big";
  // Once it is gone, a new browser is taken again.
  std::this_thread::sleep_for(200ms);
  websocket::stream<tcp::socket> again(io_);
  again.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port_));
  again.handshake("127.0.0.1", "/ws", ec);
  EXPECT_FALSE(ec) << ec.message();
}

}  // namespace
}  // namespace pool::client::test
