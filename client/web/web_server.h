// pool-web's HTTP and WebSocket side (Boost.Beast on one Asio thread): the page's files from
// memory, and /ws, where each browser gets the gateway's messages through a bounded queue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "client/web/gateway.h"
#include "core/check.h"

#include <boost/asio/ip/address.hpp>

namespace boost::asio {
class io_context;
}

namespace pool::web {

struct WebServerOptions {
  std::string bind = "127.0.0.1";
  std::uint16_t port = 8080;   ///< 0: any free port (see WebServer::port)
  std::filesystem::path root;  ///< the page's folder (index.html, app.js, three.module.js, ...)
  std::size_t queue_bytes = 4u << 20;  ///< a browser's queue budget: past it, it is dropped
  /// WebSocket connections at once. When all are taken, a browser from an address holding at
  /// least two fewer than the address holding the most takes the oldest of that address's;
  /// otherwise it is answered 503.
  std::size_t max_browsers = 256;
  /// HTTP connections not (yet) upgraded to a WebSocket, shared among addresses as the browsers
  /// are; past them a new connection is closed unanswered.
  std::size_t max_pending = 64;
  /// Seconds to receive a whole HTTP request (the upgrade included), and to send a response.
  double http_timeout = 10.0;
  /// Seconds a WebSocket may stay silent: it is pinged after half of it (a browser answers by
  /// itself) and closed when nothing at all came back by its end.
  double idle_timeout = 30.0;
};

/// The key a connection's slots are shared by: an IPv4 address (a mapped one as IPv4), or an
/// IPv6 address's /64 (one host's usual share of a network).
std::string addressKey(const boost::asio::ip::address& address);

/// The page's files, read once at start: every regular file directly in `root` whose name is
/// made of [A-Za-z0-9._-], by name. Fails when `root` has no index.html.
Result<std::map<std::string, std::string>> loadPage(const std::filesystem::path& root);

/// The page's meshes, read once at start: each regular file `<dir>/tables/<name>.obj` and
/// `<dir>/hall/<name>.obj` (names of [A-Za-z0-9_-]), served as /assets/tables/<name>.obj and
/// /assets/hall/<name>.obj. A folder that cannot be listed adds nothing.
std::map<std::string, std::string> loadAssets(const std::filesystem::path& dir);

/// Points the bare 'three' imports of the three.js add-ons the page imports (OBJLoader.js,
/// BufferGeometryUtils.js, copied beside the page by the build) at three.module.js. The names of
/// those missing from `files`.
std::vector<std::string> addThreeAddons(std::map<std::string, std::string>& files);

/// Whether `name` (a request's path less its leading '/') is one the server may answer with a
/// file: a page file's name or assets/<folder>/<name>.obj.
bool servedName(const std::string& name);

/// The Content-Type of a page file by its extension.
const char* contentType(const std::string& name);

/// Listens on the options' address and serves until the io_context stops. Every handler runs on
/// the io_context's thread, the gateway's too.
class WebServer {
 public:
  WebServer(boost::asio::io_context& io, Gateway& gateway, WebServerOptions options,
            std::map<std::string, std::string> files);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  /// Binds and listens, or refuses with why it cannot.
  Check<> start();
  /// The port listened on (after start).
  std::uint16_t port() const;
  /// Browsers dropped for being too slow, and connections refused for being too many.
  std::uint64_t dropped() const;
  std::uint64_t refused() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace pool::web
