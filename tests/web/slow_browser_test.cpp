// Real sockets: a browser that stops reading is dropped by pool-web once its queue is full, and a
// browser beside it on the same match keeps getting every frame meanwhile.
#include <gtest/gtest.h>

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <sys/socket.h>
#include <sys/time.h>
#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "support/client_fixture.h"
#include "support/match_recorder.h"

namespace pool::client::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class SlowBrowserTest : public ClientIntegrationTest {};

/// A connected WebSocket watching `match` (throws on failure).
std::unique_ptr<websocket::stream<tcp::socket>> browser(asio::io_context& io, std::uint16_t port,
                                                        const std::string& match,
                                                        int receive_buffer = 0) {
  auto ws = std::make_unique<websocket::stream<tcp::socket>>(io);
  auto& socket = ws->next_layer();
  socket.open(tcp::v4());
  if (receive_buffer > 0) socket.set_option(asio::socket_base::receive_buffer_size(receive_buffer));
  socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  ws->handshake("127.0.0.1", "/ws");
  ws->write(asio::buffer(nlohmann::json{{"watch", match}}.dump()));
  return ws;
}

TEST_F(SlowBrowserTest, ABrowserThatStopsReadingIsDroppedAndTheOtherKeepsEveryFrame) {
  open(kWebSlowBrowser, "web-slow");
  MatchRecorder recorder(kWebSlowBrowser);
  // Frames paced at 60 Hz (about 80 kB/s of JSON while balls move): a queue of 64 KiB never fills
  // for a browser that reads, and fills within seconds for one that does not (once the kernel's
  // socket buffers are full).
  startServer({});
  startBot("alice", 3, {"--think", "0.3"});
  startBot("bob", 4, {"--think", "0.3"});
  ChildProcess& web =
      start("pool-web",
            {"--domain", std::to_string(domain_), "--port", "0", "--root",
             std::string(POOL_BIN_DIR) + "/../web", "--queue-kib", "64", "--stats", "0.2"},
            "web");
  std::uint16_t port = 0;
  const std::regex url("http://127\\.0\\.0\\.1:([0-9]+)/");
  for (const auto until = std::chrono::steady_clock::now() + 20s;
       !port && std::chrono::steady_clock::now() < until && web.running();) {
    std::smatch m;
    const std::string out = web.out();
    if (std::regex_search(out, m, url)) port = static_cast<std::uint16_t>(std::stoi(m[1]));
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_NE(port, 0) << logs();
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return v && inPlay(v->phase);
  })) << logs();
  const std::string match = recorder.firstMatch();

  asio::io_context io;
  const auto watch_from = std::chrono::steady_clock::now();
  auto slow = browser(io, port, match, 4096);  // never read again
  auto fast = browser(io, port, match);
  std::atomic<int> frames{0};
  std::atomic<bool> fast_closed{false};
  std::thread reader([&] {
    beast::flat_buffer buffer;
    beast::error_code ec;
    while (!ec) {
      fast->read(buffer, ec);
      if (ec) break;
      const auto m = nlohmann::json::parse(beast::buffers_to_string(buffer.data()), nullptr, false);
      buffer.consume(buffer.size());
      if (!m.is_discarded() && m.value("type", "") == "frame") ++frames;
    }
    fast_closed = true;
  });

  // pool-web says it dropped a browser (its counters every 0.2 s).
  const std::regex dropped("dropped ([1-9][0-9]*)");
  bool was_dropped = false;
  const auto until = std::chrono::steady_clock::now() + 45s;
  while (!was_dropped && std::chrono::steady_clock::now() < until && web.running()) {
    recorder.pump(100ms);
    const std::string err = web.err();
    was_dropped = std::regex_search(err, dropped);
  }
  EXPECT_TRUE(was_dropped) << "the browser that stopped reading was never dropped\n" << logs();
  const auto dropped_at = std::chrono::steady_clock::now();

  // The other browser still gets frames after the drop: another shot's at least.
  const int at_drop = frames.load();
  const std::uint32_t shot_at_drop = recorder.latest(match)->shot_number;
  EXPECT_TRUE(recorder.pump(45s,
                            [&] {
                              const MatchView* v = recorder.latest(match);
                              return (v && v->shot_number >= shot_at_drop + 2 &&
                                      frames.load() > at_drop + 20) ||
                                     fast_closed.load();
                            }))
      << "frames " << frames.load() << " at drop " << at_drop << "\n"
      << logs();
  EXPECT_FALSE(fast_closed.load()) << "the reading browser was dropped too";
  std::printf("dropped after %.1f s; the other browser had %d frames then, %d one shot later\n",
              std::chrono::duration<double>(dropped_at - watch_from).count(), at_drop,
              frames.load());
  EXPECT_GT(frames.load(), at_drop);

  // The dropped browser's connection was closed by pool-web: reading it ends in an error once
  // what was buffered is read.
  if (was_dropped) {
    // A read that waits 5 s for nothing fails with a timeout, not with the end of the stream.
    const timeval wait{5, 0};
    ::setsockopt(slow->next_layer().native_handle(), SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    beast::flat_buffer buffer;
    beast::error_code ec;
    for (int i = 0; i < 100000 && !ec; ++i) {
      slow->read(buffer, ec);
      buffer.consume(buffer.size());
    }
    EXPECT_TRUE(ec == websocket::error::closed || ec == asio::error::eof ||
                ec == asio::error::connection_reset || ec == beast::error::timeout ||
                ec == asio::error::broken_pipe)
        << "the slow browser's connection ends with: " << ec.message();
    EXPECT_NE(ec, asio::error::would_block) << "the slow browser's connection is still open";
  }

  beast::error_code ignored;
  fast->next_layer().shutdown(tcp::socket::shutdown_both, ignored);
  fast->next_layer().close(ignored);
  reader.join();
}

}  // namespace
}  // namespace pool::client::test
