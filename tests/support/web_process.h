// pool-web as a child process for tests, and raw sockets to it from a chosen loopback address
// (127.x.y.z: pool-web shares its slots per source address, and loopback has them all).
#pragma once

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <sys/socket.h>
#include <boost/asio.hpp>
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

/// Runs a function when it goes out of scope: a test's reading thread is stopped and joined even
/// when an assertion ends the test early (a joinable thread destroyed would abort the run).
class AtScopeExit {
 public:
  explicit AtScopeExit(std::function<void()> run) : run_(std::move(run)) {}
  ~AtScopeExit() { run_(); }
  AtScopeExit(const AtScopeExit&) = delete;
  AtScopeExit& operator=(const AtScopeExit&) = delete;

 private:
  std::function<void()> run_;
};

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
