// pool-web as a child process for tests, and raw sockets to it from a chosen loopback address
// (127.x.y.z: pool-web shares its slots per source address, and loopback has them all).
#pragma once

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <sys/socket.h>
#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <cerrno>
#include <chrono>
#include <functional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "support/child_process.h"

namespace pool::client::test {

/// The port a started pool-web prints in its URL, waiting up to 20 s; 0 when it never did.
inline std::uint16_t webPort(ChildProcess& web) {
  const std::regex url("http://127\\.0\\.0\\.1:([0-9]+)/");
  for (const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
       std::chrono::steady_clock::now() < until && web.running();) {
    std::smatch m;
    const std::string out = web.out();
    if (std::regex_search(out, m, url)) return static_cast<std::uint16_t>(std::stoi(m[1]));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return 0;
}

/// pool-web's arguments for `domain` on any free port with the built page, then `extra`.
inline std::vector<std::string> webArgs(std::uint32_t domain,
                                        const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args{"--domain", std::to_string(domain),
                                "--port",   "0",
                                "--root",   std::string(POOL_BIN_DIR) + "/../web"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

/// A TCP socket connected to 127.0.0.1:`port` from `source` (throws on failure).
inline boost::asio::ip::tcp::socket connectFrom(boost::asio::io_context& io,
                                                const std::string& source, std::uint16_t port) {
  namespace asio = boost::asio;
  asio::ip::tcp::socket socket(io);
  socket.open(asio::ip::tcp::v4());
  socket.bind(asio::ip::tcp::endpoint(asio::ip::make_address(source), 0));
  socket.connect(asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  return socket;
}

/// A browser's WebSocket read on a thread of its own (answering pings, as a browser does): each
/// message goes to `each` on that thread. The socket is shut down and the thread joined when it
/// goes, also when an assertion ends the test early (a joinable thread destroyed would abort the
/// run).
class ReadingBrowser {
 public:
  using Socket = boost::beast::websocket::stream<boost::asio::ip::tcp::socket>;

  explicit ReadingBrowser(Socket& socket, std::function<void(const std::string&)> each = {})
      : socket_(socket), thread_([this, each = std::move(each)] {
          boost::beast::flat_buffer in;
          boost::beast::error_code ec;
          for (;;) {
            socket_.read(in, ec);
            if (ec) break;
            if (each) each(boost::beast::buffers_to_string(in.data()));
            in.consume(in.size());
          }
          closed_ = true;
        }) {}
  ~ReadingBrowser() {
    boost::beast::error_code ignored;
    socket_.next_layer().shutdown(boost::asio::ip::tcp::socket::shutdown_both, ignored);
    thread_.join();
  }
  ReadingBrowser(const ReadingBrowser&) = delete;
  ReadingBrowser& operator=(const ReadingBrowser&) = delete;

  /// Whether its reading ended before the test stopped it (pool-web closed it, or a read failed).
  bool closed() const { return closed_.load(); }

 private:
  Socket& socket_;
  std::atomic<bool> closed_{false};
  std::thread thread_;  ///< last: starts once the rest is made
};

/// Polls `done` every 20 ms until it holds or `limit` passes; whether it held.
template <class Done>
bool pollUntil(Done&& done, std::chrono::seconds limit) {
  for (const auto until = std::chrono::steady_clock::now() + limit;
       std::chrono::steady_clock::now() < until;) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return done();
}

/// Whether the peer has closed `socket` (what it sent before is read and discarded first).
inline bool closedByPeer(boost::asio::ip::tcp::socket& socket) {
  char buffer[65536];
  for (;;) {
    const auto n = ::recv(socket.native_handle(), buffer, sizeof buffer, MSG_DONTWAIT);
    if (n == 0) return true;
    if (n < 0) return errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR;
  }
}

}  // namespace pool::client::test
