// Benchmark: pool-web with 50 browsers (WebSocket clients) on one match of a real pool-server.
// Prints the gateway's CPU, memory and bytes per browser per second, and the frame rates the
// server keeps for its other match, against a run of the same server without the gateway.
#include <sys/resource.h>
#include <unistd.h>

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange without it

#include <algorithm>
#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "client/net/game_client.h"
#include "support/child_process.h"
#include "support/domain_claim.h"

namespace {

using namespace pool;
using pool::client::test::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

constexpr std::uint32_t kDomain = 42;  // 40–59: the web spectator's

double seconds(Clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

/// CPU seconds (user + system) a process has used, from /proc.
double cpuSeconds(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (close == std::string::npos) return 0.0;
  std::istringstream fields(text.substr(close + 2));
  std::string f;
  double utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> f; ++i) {
    if (i == 14) utime = std::stod(f);
    if (i == 15) stime = std::stod(f);
  }
  return (utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

/// A line of /proc/<pid>/status in kB (VmRSS, VmHWM).
long statusKb(pid_t pid, const std::string& key) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key + ":", 0) == 0) return std::stol(line.substr(key.size() + 1));
  }
  return 0;
}

/// Frame arrival times of one match, per shot, as a spectator sees them.
struct FrameRates {
  std::map<std::uint32_t, std::vector<double>> arrivals;  ///< by shot number

  /// Median over shots of frames per second within the shot (shots with 30+ frames), and the
  /// 99th percentile gap between consecutive frames, ms.
  std::pair<double, double> summary() const {
    std::vector<double> rates, gaps;
    for (const auto& [shot, t] : arrivals) {
      if (t.size() < 30) continue;
      rates.push_back(static_cast<double>(t.size() - 1) / (t.back() - t.front()));
      for (std::size_t i = 1; i < t.size(); ++i) gaps.push_back(1000 * (t[i] - t[i - 1]));
    }
    if (rates.empty()) return {0, 0};
    std::sort(rates.begin(), rates.end());
    std::sort(gaps.begin(), gaps.end());
    return {rates[rates.size() / 2],
            gaps[static_cast<std::size_t>(0.99 * static_cast<double>(gaps.size() - 1))]};
  }
  std::size_t shots() const {
    std::size_t n = 0;
    for (const auto& [shot, t] : arrivals) n += t.size() >= 30 ? 1 : 0;
    return n;
  }
};

/// Follows `match` for `span`, recording its frames' arrivals.
FrameRates watchFrames(client::GameClient& spectator, const std::string& match,
                       Clock::duration span) {
  FrameRates rates;
  const auto t0 = Clock::now();
  while (Clock::now() - t0 < span) {
    spectator.wait(5ms);
    for (const auto& event : spectator.poll()) {
      if (const auto* f = std::get_if<client::TableFrame>(&event); f && f->match == match) {
        rates.arrivals[f->shot_number].push_back(seconds(Clock::now() - t0));
      }
    }
  }
  return rates;
}

/// Polls `ready` every 20 ms for up to `limit`; whether it came true.
template <class Ready>
bool waitUntil(Clock::duration limit, Ready ready) {
  for (const auto until = Clock::now() + limit; Clock::now() < until;) {
    if (ready()) return true;
    std::this_thread::sleep_for(20ms);
  }
  return ready();
}

/// Waits up to `limit` for a frame of `match` (a shot in flight); whether one came.
bool nextFrame(client::GameClient& spectator, const std::string& match, Clock::duration limit) {
  for (const auto until = Clock::now() + limit; Clock::now() < until;) {
    spectator.wait(5ms);
    for (const auto& event : spectator.poll()) {
      if (const auto* f = std::get_if<client::TableFrame>(&event); f && f->match == match) {
        return true;
      }
    }
  }
  return false;
}

/// `count` WebSocket browsers watching `match` on one Asio thread, counting the bytes they get.
class Browsers {
 public:
  Browsers(std::uint16_t port, const std::string& match, int count) {
    for (int i = 0; i < count; ++i) {
      auto b = std::make_shared<Browser>(io_);
      browsers_.push_back(b);
      connect(b, port, match);
    }
    thread_ = std::thread([this] { io_.run(); });
  }
  ~Browsers() {
    io_.stop();
    thread_.join();
  }
  /// Bytes each browser got so far, and how many were closed.
  std::vector<std::uint64_t> bytes() const {
    std::vector<std::uint64_t> out;
    for (const auto& b : browsers_) out.push_back(b->bytes.load());
    return out;
  }
  /// Browsers that got at least one message (the gateway's answer to their watch).
  int joined() const {
    int n = 0;
    for (const auto& b : browsers_) n += b->bytes.load() > 0 ? 1 : 0;
    return n;
  }
  int closed() const {
    int n = 0;
    for (const auto& b : browsers_) n += b->closed.load() ? 1 : 0;
    return n;
  }

 private:
  struct Browser {
    explicit Browser(asio::io_context& io) : ws(io) {}
    websocket::stream<tcp::socket> ws;
    beast::flat_buffer buffer;
    std::string request;
    std::atomic<std::uint64_t> bytes{0};
    std::atomic<bool> closed{false};
  };

  void connect(const std::shared_ptr<Browser>& b, std::uint16_t port, const std::string& match) {
    b->request = "{\"watch\":\"" + match + "\"}";
    b->ws.next_layer().async_connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), port), [b](beast::error_code ec) {
          if (ec) return void(b->closed = true);
          b->ws.async_handshake("127.0.0.1", "/ws", [b](beast::error_code ec2) {
            if (ec2) return void(b->closed = true);
            b->ws.async_write(asio::buffer(b->request), [b](beast::error_code ec3, std::size_t) {
              if (ec3) return void(b->closed = true);
              read(b);
            });
          });
        });
  }
  static void read(const std::shared_ptr<Browser>& b) {
    b->ws.async_read(b->buffer, [b](beast::error_code ec, std::size_t n) {
      if (ec) return void(b->closed = true);
      b->bytes += n;
      b->buffer.consume(b->buffer.size());
      read(b);
    });
  }

  asio::io_context io_;
  std::vector<std::shared_ptr<Browser>> browsers_;
  std::thread thread_;
};

}  // namespace

int main(int argc, char** argv) {
  double span = 12.0;  // s measured in each run
  int browsers = 50;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--benchmark_min_time=", 0) == 0) {
      // The suite's smoke run: short windows, the same figures.
      span = std::stod(arg.substr(21)) < 1.0 ? 3.0 : span;
    } else if (arg == "--seconds" && i + 1 < argc) {
      span = std::stod(argv[++i]);
    } else if (arg == "--browsers" && i + 1 < argc) {
      browsers = std::stoi(argv[++i]);
    }
  }
  client::test::useLoopbackConfig();
  pool::test::DomainClaim claim(kDomain);
  if (!claim.claimed()) {
    std::fprintf(stderr, "web_bench: %s\n", claim.refusal().c_str());
    return 1;
  }
  client::test::ScratchDir scratch("web-bench");
  ::setenv("XDG_DATA_HOME", scratch.file("data").c_str(), 1);
  const std::string domain = std::to_string(kDomain);
  ChildProcess server("pool-server", {"--domain", domain, "--tables", "2", "--server-id", "bench"},
                      scratch.file("server.out"), scratch.file("server.err"));
  std::vector<std::unique_ptr<ChildProcess>> bots;
  for (const auto& [name, match] : std::vector<std::pair<std::string, std::string>>{
           {"ann", "bench-1"}, {"ben", "bench-1"}, {"cat", "bench-2"}, {"dan", "bench-2"}}) {
    bots.push_back(std::make_unique<ChildProcess>(
        "pool-bot",
        std::vector<std::string>{"--domain", domain, "--name", name, "--match", match, "--skill",
                                 "0.6", "--timeout", "300", "--think", "0.2"},
        scratch.file(name + ".out"), scratch.file(name + ".err")));
  }
  client::GameClient spectator({kDomain, "", "bench", {}, [](auto&&...) {}});
  spectator.observe("bench-1");  // each match's states travel in its own partition
  spectator.observe("bench-2");
  // Both matches in play before measuring.
  const auto ready_by = Clock::now() + 60s;
  while (Clock::now() < ready_by) {
    spectator.wait(20ms);
    spectator.poll();
    const auto* a = spectator.state("bench-1");
    const auto* b = spectator.state("bench-2");
    if (a && b && protocol::inPlay(a->phase) && protocol::inPlay(b->phase)) break;
  }
  if (!spectator.state("bench-2") || !spectator.state("bench-1")) {
    std::fprintf(stderr, "web_bench: the two matches did not start\n%s\n", server.err().c_str());
    return 1;
  }
  const auto window =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(span));

  std::printf(
      "web_bench: %d browsers on bench-1, the server's frames of bench-2 meanwhile, %.0f s each "
      "run\n",
      browsers, span);
  // Run A: no gateway.
  double server_cpu0 = cpuSeconds(server.pid());
  const FrameRates base = watchFrames(spectator, "bench-2", window);
  const double server_cpu_base = (cpuSeconds(server.pid()) - server_cpu0) / span;

  // Run B: pool-web with `browsers` browsers on bench-1.
  ChildProcess web(
      "pool-web",
      {"--domain", domain, "--port", "0", "--root", std::string(POOL_BIN_DIR) + "/../web"},
      scratch.file("web.out"), scratch.file("web.err"));
  std::uint16_t port = 0;
  const std::regex url("http://127\\.0\\.0\\.1:([0-9]+)/");
  for (const auto until = Clock::now() + 20s; !port && Clock::now() < until;) {
    std::smatch m;
    const std::string out = web.out();
    if (std::regex_search(out, m, url)) port = static_cast<std::uint16_t>(std::stoi(m[1]));
    std::this_thread::sleep_for(20ms);
  }
  if (!port) {
    std::fprintf(stderr, "web_bench: pool-web did not start\n%s\n", web.err().c_str());
    return 1;
  }
  Browsers clients(port, "bench-1", browsers);
  // Every browser joined (the gateway answers a watch at once), then the window opens on a shot
  // of bench-1 in flight, so that it holds frames to fan out however long the bots think (under
  // the sanitizers a bot's turn can outlast a smoke run's window).
  if (!waitUntil(60s, [&] { return clients.joined() == browsers; })) {
    std::fprintf(stderr, "web_bench: %d of %d browsers joined in 60 s\n%s\n", clients.joined(),
                 browsers, web.err().c_str());
    return 1;
  }
  if (!nextFrame(spectator, "bench-1", 60s)) {
    std::fprintf(stderr, "web_bench: bench-1 played no shot in 60 s\n%s\n", server.err().c_str());
    return 1;
  }
  const auto bytes0 = clients.bytes();
  const double web_cpu0 = cpuSeconds(web.pid());
  server_cpu0 = cpuSeconds(server.pid());
  const auto t0 = Clock::now();
  const FrameRates loaded = watchFrames(spectator, "bench-2", window);
  const double measured = seconds(Clock::now() - t0);
  const auto bytes1 = clients.bytes();
  const double web_cpu = (cpuSeconds(web.pid()) - web_cpu0) / measured;
  const double server_cpu_loaded = (cpuSeconds(server.pid()) - server_cpu0) / measured;
  std::vector<double> rates;
  for (std::size_t i = 0; i < bytes0.size(); ++i)
    rates.push_back(static_cast<double>(bytes1[i] - bytes0[i]) / measured);
  std::sort(rates.begin(), rates.end());
  double total = 0;
  for (double r : rates) total += r;

  const auto [base_fps, base_gap] = base.summary();
  const auto [loaded_fps, loaded_gap] = loaded.summary();
  std::printf(
      "gateway: CPU %.1f%% of a core, RSS %ld kB (peak %ld kB), browsers dropped %d of %d\n",
      100 * web_cpu, statusKb(web.pid(), "VmRSS"), statusKb(web.pid(), "VmHWM"), clients.closed(),
      browsers);
  std::printf("per browser: %.0f B/s mean, %.0f B/s min, %.0f B/s max (all: %.0f kB/s)\n",
              total / static_cast<double>(rates.size()), rates.front(), rates.back(), total / 1024);
  std::printf("server CPU: %.1f%% of a core without the gateway, %.1f%% with it\n",
              100 * server_cpu_base, 100 * server_cpu_loaded);
  std::printf(
      "bench-2 frames (the other match), without the gateway: %.1f fps median over %zu "
      "shots, p99 gap %.1f ms\n",
      base_fps, base.shots(), base_gap);
  std::printf(
      "bench-2 frames (the other match), with the gateway:    %.1f fps median over %zu "
      "shots, p99 gap %.1f ms\n",
      loaded_fps, loaded.shots(), loaded_gap);
  // Figures only; the run fails when it measured nothing: no browser got a frame of a shot that
  // was in flight when the window opened.
  if (rates.back() > 0) return 0;
  std::fprintf(stderr, "web_bench: no browser got a frame of bench-1 in the window\n%s\n",
               web.err().c_str());
  return 1;
}
