// pool-web: the web spectator's gateway. Joins the DDS domain as a spectator and serves the page
// and its WebSocket stream over HTTP.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>

#include "client/net/game_client.h"
#include "client/render/hall_assets.h"
#include "client/render/lamps.h"
#include "client/render/obj_text.h"
#include "client/web/gateway.h"
#include "client/web/web_server.h"
#include "core/program_dir.h"
#include "table/assets.h"

namespace {

/// The page's folder beside the program: <bin>/../web in a build tree, <bin>/../share/pool/web
/// installed.
std::filesystem::path defaultRoot() {
  std::error_code ec;
  const auto bin = pool::programDir().value_or(std::filesystem::path());
  for (const auto& candidate : {bin / ".." / "web", bin / ".." / "share" / "pool" / "web"}) {
    if (std::filesystem::exists(candidate / "index.html", ec)) return candidate.lexically_normal();
  }
  return bin / ".." / "share" / "pool" / "web";
}

/// The meshes the page draws the hall with: assets/'s tables and hall, a dressing made for each
/// table that has none there (as the game's renderer makes it), and the lamps' shade.
std::map<std::string, std::string> pageMeshes(const std::filesystem::path& assets) {
  auto meshes = pool::web::loadAssets(assets);
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(assets / "tables", ec)) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().stem().string();
    const std::string dressing = "assets/hall/" + name + ".obj";
    if (!meshes.count("assets/tables/" + name + ".obj") || meshes.count(dressing)) continue;
    if (auto text = pool::render::dressingObj(name)) meshes[dressing] = std::move(*text);
  }
  // The shade and its cord apart (the cord's triangles reach above the shade's top).
  const pool::render::MeshData lamp = pool::render::lampShade();
  pool::render::MeshData shade, cord;
  for (std::size_t i = 0; i + 2 < lamp.positions.size(); i += 3) {
    const float top =
        std::max({lamp.positions[i].z, lamp.positions[i + 1].z, lamp.positions[i + 2].z});
    auto& part = top > pool::render::kShadeBound ? cord : shade;
    for (std::size_t k = i; k < i + 3; ++k) {
      part.positions.push_back(lamp.positions[k]);
      part.normals.push_back(lamp.normals[k]);
    }
  }
  meshes["assets/hall/lamp-shade.obj"] =
      pool::render::objText({{"shade", shade}, {"cord", cord}},
                            {"A lamp's shade round its light at the origin, and its cord."});
  return meshes;
}

/// Everything pool-web can be told.
struct WebConfig {
  std::uint32_t domain = 0;
  pool::web::WebServerOptions options;
  std::string root;  ///< the page's folder; empty: beside the program
  std::string pins;  ///< file of pinned server keys; empty: in memory
  std::size_t queue_kib = pool::web::WebServerOptions{}.queue_bytes / 1024;
  double stats_every = 0.0;  ///< s between counters on stderr; 0: never
};

/// Every flag of pool-web, bound to its field of `c`.
void addWebFlags(CLI::App& app, WebConfig& c) {
  app.add_option("--domain", c.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--bind", c.options.bind, "address to listen on (default: loopback only)");
  app.add_option("--port", c.options.port, "TCP port (0: any free port; the URL is printed)");
  app.add_option("--root", c.root, "the page's folder (default: beside the program)");
  app.add_option("--server-pins", c.pins,
                 "file of pinned server keys (default: pinned in memory for this run)");
  app.add_option("--queue-kib", c.queue_kib,
                 "a browser's queue of unsent messages, KiB: past it the browser is dropped")
      ->check(CLI::Range(16, 1 << 20));
  app.add_option("--max-browsers", c.options.max_browsers,
                 "WebSocket connections at once (shared fairly among addresses)")
      ->check(CLI::Range(1, 10000));
  app.add_option("--max-pending", c.options.max_pending,
                 "HTTP connections not upgraded to a WebSocket at once (shared fairly among "
                 "addresses)")
      ->check(CLI::Range(1, 10000));
  app.add_option("--http-timeout", c.options.http_timeout,
                 "seconds to receive a whole HTTP request, and to send a response")
      ->check(CLI::Range(0.1, 3600.0));
  app.add_option("--idle-timeout", c.options.idle_timeout,
                 "seconds a WebSocket may stay silent (pinged after half of it, closed at its end)")
      ->check(CLI::Range(0.2, 3600.0));
  app.add_option("--stats", c.stats_every, "print counters to stderr every S seconds (0: never)");
}

/// Serves the page and the domain's matches until SIGINT or SIGTERM; the exit status.
int serve(WebConfig c) {
  c.options.queue_bytes = c.queue_kib * 1024;
  c.options.root = c.root.empty() ? defaultRoot() : std::filesystem::path(c.root);
  auto files = pool::web::loadPage(c.options.root);
  if (!files) {
    std::cerr << "pool-web: " << files.error() << '\n';
    return 1;
  }
  const std::filesystem::path assets = pool::table::assetsDir();
  files->merge(pageMeshes(assets));
  const auto missing = pool::web::addThreeAddons(*files);
  for (const auto& name : missing) {
    std::cerr << "pool-web: no " << name << " (three.js's add-on) in " << c.options.root.string()
              << ": the page draws the table without the hall's meshes\n";
  }
  pool::client::GameClient client(
      {c.domain, "", "web", c.pins, [](const std::string& line, bool problem) {
         std::cerr << "pool-web: " << (problem ? "dropped: " : "") << line << '\n';
       }});
  client.openHistory();  // replays: the server matches our request writer before a browser asks
  // The lobby message takes at most a quarter of a browser's queue.
  pool::web::LobbyLimits lobby_limits;
  lobby_limits.served_bytes = c.options.queue_bytes / 4;
  pool::web::Gateway gateway(client, 1.0, lobby_limits);
  boost::asio::io_context io;
  pool::web::WebServer server(io, gateway, c.options, std::move(*files));
  if (auto started = server.start(); !started) {
    std::cerr << "pool-web: " << started.error() << '\n';
    return 1;
  }
  std::cout << "pool-web: http://" << c.options.bind << ":" << server.port() << "/ (domain "
            << c.domain << ")" << std::endl;

  boost::asio::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](const boost::system::error_code&, int) { io.stop(); });
  // DDS is polled on the same thread as the sockets: every 5 ms, a frame's latency at most.
  const auto start = std::chrono::steady_clock::now();
  boost::asio::steady_timer tick(io);
  double last_stats = 0.0;
  std::function<void()> poll = [&] {
    const double now =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    gateway.step(now);
    if (c.stats_every > 0 && now - last_stats >= c.stats_every) {
      last_stats = now;
      std::cerr << "pool-web: browsers " << gateway.browsers() << ", messages "
                << gateway.stats().messages << ", deliveries " << gateway.stats().deliveries
                << ", lobby " << gateway.lobby().size() << " kept " << gateway.stats().lobby_refused
                << " refused, dropped " << server.dropped() << '\n';
    }
    tick.expires_after(std::chrono::milliseconds(5));
    tick.async_wait([&](const boost::system::error_code& ec) {
      if (!ec) poll();
    });
  };
  poll();
  io.run();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  WebConfig config;
  CLI::App app{"pool-web: watch the matches of the DDS domain from a browser"};
  addWebFlags(app, config);
  CLI11_PARSE(app, argc, argv);
  try {
    return serve(config);
  } catch (const std::exception& e) {
    std::cerr << "pool-web: " << e.what() << '\n';
    return 1;
  }
}
