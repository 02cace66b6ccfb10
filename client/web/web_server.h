// pool-web's HTTP and WebSocket side (Boost.Beast on one Asio thread): the page's files from
// memory, and /ws, where each browser gets the gateway's messages through a bounded queue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "client/web/gateway.h"

namespace boost::asio {
class io_context;
}

namespace pool::web {

struct WebServerOptions {
  std::string bind = "127.0.0.1";
  std::uint16_t port = 8080;   ///< 0: any free port (see WebServer::port)
  std::filesystem::path root;  ///< the page's folder (index.html, app.js, three.module.js, ...)
  std::size_t queue_bytes = 4u << 20;  ///< a browser's queue budget: past it, it is dropped
  /// WebSocket connections at once; more are answered 503 (and past 64 more connections of any
  /// kind, new ones are closed unanswered).
  std::size_t max_browsers = 256;
};

/// The page's files, read once at start: every regular file directly in `root` whose name is
/// made of [A-Za-z0-9._-], by name. Fails when `root` has no index.html.
Result<std::map<std::string, std::string>> loadPage(const std::filesystem::path& root);

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

  /// Binds and listens; empty when listening, else why not.
  std::string start();
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
