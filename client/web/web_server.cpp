// Boost.Beast HTTP and WebSocket sessions on one Asio thread: static page files from memory,
// /ws for the gateway's messages, a bounded queue per browser, slow browsers dropped.
#include "client/web/web_server.h"

#include "client/web/fair_slots.h"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace pool::web {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

struct WebServer::State {
  State(asio::io_context& io_context, Gateway& g, WebServerOptions o,
        std::map<std::string, std::string> f)
      : io(io_context),
        gateway(g),
        options(std::move(o)),
        files(std::move(f)),
        acceptor(io),
        pending(options.max_pending),
        browsers(options.max_browsers) {}
  asio::io_context& io;
  Gateway& gateway;
  WebServerOptions options;
  std::map<std::string, std::string> files;
  tcp::acceptor acceptor;
  std::uint64_t next_browser = 1;
  FairSlots pending;   ///< HTTP connections not upgraded, by slot id
  FairSlots browsers;  ///< WebSockets, by slot id
  std::uint64_t next_slot = 1;
  /// How to close the holder of each slot (when another address takes it back).
  std::map<std::uint64_t, std::function<void()>> closers;
  std::uint64_t dropped = 0;
  std::uint64_t refused = 0;
};

namespace {

using State = WebServer::State;

/// A browser socket's kernel send buffer, bytes (Linux doubles it): far more than a match's
/// stream needs in flight on a LAN (about 80 kB/s while balls move).
constexpr int kSendBuffer = 128 * 1024;

bool pageFileName(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.') return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

/// A mesh's name in assets/: [A-Za-z0-9_-] then ".obj".
bool assetMeshName(const std::string& name) {
  const std::string ext = ".obj";
  if (name.size() <= ext.size() || name.size() > 64) return false;
  if (name.compare(name.size() - ext.size(), ext.size(), ext) != 0) return false;
  for (std::size_t i = 0; i + ext.size() < name.size(); ++i) {
    const char c = name[i];
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

/// The folders of assets/ the page's meshes come from.
constexpr const char* kAssetFolders[] = {"tables", "hall"};

std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(s));
}

/// Holds a slot of one of the state's pools until released or destroyed, with the way to close
/// its connection should another address take the slot back.
class Slot {
 public:
  Slot(std::shared_ptr<State> state, FairSlots State::*pool, std::uint64_t id)
      : state_(std::move(state)), pool_(pool), id_(id) {}
  ~Slot() { release(); }
  Slot(const Slot&) = delete;
  Slot& operator=(const Slot&) = delete;

  void onEvict(std::function<void()> close) {
    if (id_) state_->closers[id_] = std::move(close);
  }
  void release() {
    if (!id_) return;
    ((*state_).*pool_).release(id_);
    state_->closers.erase(id_);
    id_ = 0;
  }

 private:
  std::shared_ptr<State> state_;
  FairSlots State::*pool_;
  std::uint64_t id_;
};

/// Closes the connection whose slot was taken back, if any.
void evict(State& state, const std::optional<std::uint64_t>& slot) {
  if (!slot) return;
  const auto it = state.closers.find(*slot);
  if (it == state.closers.end()) return;
  const std::function<void()> close = std::move(it->second);
  state.closers.erase(it);
  ++state.refused;
  close();
}

/// One browser's WebSocket: reads its watch requests, writes the gateway's messages in order.
class BrowserSession : public std::enable_shared_from_this<BrowserSession> {
 public:
  BrowserSession(tcp::socket&& socket, std::shared_ptr<State> state, std::uint64_t slot)
      : slot_(state, &State::browsers, slot),
        ws_(std::move(socket)),
        state_(std::move(state)),
        queue_(state_->options.queue_bytes) {}

  void accept(http::request<http::string_body> request) {
    // A kernel send buffer of its own size (not grown by autotuning up to megabytes): what a
    // browser has not taken shows in its queue, which decides when it is too slow.
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().set_option(
        asio::socket_base::send_buffer_size(kSendBuffer), ignored);
    websocket::stream_base::timeout timeouts;
    timeouts.handshake_timeout = seconds(state_->options.http_timeout);
    timeouts.idle_timeout = seconds(state_->options.idle_timeout);
    timeouts.keep_alive_pings = true;
    ws_.set_option(timeouts);
    ws_.read_message_max(4096);
    ws_.text(true);
    slot_.onEvict([weak = weak_from_this()] {
      if (const auto self = weak.lock()) self->close(true);
    });
    ws_.async_accept(request,
                     [self = shared_from_this()](beast::error_code ec) { self->onAccept(ec); });
  }

 private:
  void onAccept(beast::error_code ec) {
    if (ec) return close(false);
    id_ = state_->next_browser++;
    attached_ = true;
    state_->gateway.attach(id_, [weak = weak_from_this()](const Message& message) {
      const auto self = weak.lock();
      return self && self->push(message);
    });
    read();
  }

  /// Queues a message; false (the browser dropped) past its budget.
  bool push(const Message& message) {
    if (closed_) return false;
    if (!queue_.push(message)) {
      ++state_->dropped;
      // The gateway detaches us itself when we say no (we are inside its fan-out).
      attached_ = false;
      close(false);
      return false;
    }
    if (!writing_) write();
    return true;
  }

  void write() {
    writing_ = true;
    ws_.async_write(
        asio::buffer(*queue_.front()),
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->onWrite(ec); });
  }

  void onWrite(beast::error_code ec) {
    writing_ = false;
    if (ec || closed_) return close(true);
    queue_.pop();
    if (!queue_.empty()) write();
  }

  void read() {
    ws_.async_read(
        in_, [self = shared_from_this()](beast::error_code ec, std::size_t) { self->onRead(ec); });
  }

  void onRead(beast::error_code ec) {
    if (ec || closed_) return close(true);
    const std::string text = beast::buffers_to_string(in_.data());
    in_.consume(in_.size());
    std::string error;
    if (const auto request = parseRequest(text, error)) {
      if (const auto* watch = std::get_if<WatchRequest>(&*request)) {
        state_->gateway.watch(id_, watch->match);
      } else if (const auto* replay = std::get_if<ReplayRequest>(&*request)) {
        state_->gateway.replay(id_, replay->match, replay->shot);
      }
    } else {
      push(std::make_shared<const std::string>(
          nlohmann::json{{"type", "error"}, {"text", "bad request: " + error}}.dump()));
    }
    if (!closed_) read();
  }

  void close(bool detach) {
    if (closed_) return;
    closed_ = true;
    if (detach && attached_) state_->gateway.detach(id_);
    attached_ = false;
    slot_.release();
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  Slot slot_;
  websocket::stream<beast::tcp_stream> ws_;
  std::shared_ptr<State> state_;
  OutQueue queue_;
  beast::flat_buffer in_;
  std::uint64_t id_ = 0;
  bool writing_ = false;
  bool closed_ = false;
  bool attached_ = false;
};

/// One HTTP connection: GET of the page's files, or the upgrade to /ws.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, std::shared_ptr<State> state, std::uint64_t slot,
              std::string address)
      : slot_(state, &State::pending, slot),
        stream_(std::move(socket)),
        state_(std::move(state)),
        address_(std::move(address)) {}

  void start() {
    slot_.onEvict([weak = weak_from_this()] {
      if (const auto self = weak.lock()) {
        beast::error_code ignored;
        self->stream_.socket().close(ignored);
      }
    });
    read();
  }

 private:
  void read() {
    parser_.emplace();
    parser_->header_limit(8192);
    parser_->body_limit(4096);
    stream_.expires_after(seconds(state_->options.http_timeout));
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->onRead(ec); });
  }

  void onRead(beast::error_code ec) {
    if (ec) {
      beast::error_code ignored;
      stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
      return;
    }
    http::request<http::string_body> request = parser_->release();
    const std::string target(request.target());
    const std::string path = target.substr(0, target.find('?'));
    if (websocket::is_upgrade(request) && path == "/ws") {
      const std::uint64_t slot = state_->next_slot++;
      const auto admission = state_->browsers.admit(address_, slot);
      if (!admission.admitted) {
        ++state_->refused;
        return respond(request, http::status::service_unavailable, "text/plain",
                       "too many browsers\n");
      }
      evict(*state_, admission.evicted);
      slot_.release();
      stream_.expires_never();
      std::make_shared<BrowserSession>(stream_.release_socket(), state_, slot)
          ->accept(std::move(request));
      return;
    }
    if (request.method() != http::verb::get && request.method() != http::verb::head) {
      return respond(request, http::status::method_not_allowed, "text/plain", "GET only\n");
    }
    const std::string name = path == "/" ? "index.html" : path.substr(1);
    const auto file = servedName(name) ? state_->files.find(name) : state_->files.end();
    if (file == state_->files.end()) {
      return respond(request, http::status::not_found, "text/plain", "not found\n");
    }
    respond(request, http::status::ok, contentType(name), file->second);
  }

  void respond(const http::request<http::string_body>& request, http::status status,
               const char* type, const std::string& body) {
    auto response = std::make_shared<http::response<http::string_body>>(status, request.version());
    response->set(http::field::server, "pool-web");
    response->set(http::field::content_type, type);
    response->set(http::field::cache_control, "no-cache");
    response->set("X-Content-Type-Options", "nosniff");
    response->set("Content-Security-Policy",
                  "default-src 'self'; connect-src 'self' ws: wss:; img-src 'self' data: blob:; "
                  "style-src 'self' 'unsafe-inline'");
    response->keep_alive(request.keep_alive());
    if (request.method() != http::verb::head) response->body() = body;
    response->prepare_payload();
    if (request.method() == http::verb::head) response->content_length(body.size());
    stream_.expires_after(seconds(state_->options.http_timeout));
    http::async_write(stream_, *response,
                      [self = shared_from_this(), response](beast::error_code ec, std::size_t) {
                        if (ec) return;
                        if (response->need_eof()) {
                          beast::error_code ignored;
                          self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                          return;
                        }
                        self->read();
                      });
  }

  Slot slot_;
  beast::tcp_stream stream_;
  std::shared_ptr<State> state_;
  std::string address_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

void acceptNext(const std::shared_ptr<State>& state) {
  state->acceptor.async_accept([state](beast::error_code ec, tcp::socket socket) {
    if (!state->acceptor.is_open()) return;
    if (!ec) {
      beast::error_code peer_error;
      const auto peer = socket.remote_endpoint(peer_error);
      const std::uint64_t slot = state->next_slot++;
      const std::string address = peer_error ? std::string() : addressKey(peer.address());
      const auto admission =
          peer_error ? FairSlots::Admission{} : state->pending.admit(address, slot);
      if (!admission.admitted) {
        ++state->refused;  // too many at once from this address: closed unanswered
        beast::error_code ignored;
        socket.close(ignored);
      } else {
        evict(*state, admission.evicted);
        std::make_shared<HttpSession>(std::move(socket), state, slot, address)->start();
      }
      return acceptNext(state);
    }
    // Out of file descriptors, say: try
    // again a little later rather than spin.
    auto pause = std::make_shared<asio::steady_timer>(state->io, std::chrono::milliseconds(100));
    pause->async_wait([state, pause](beast::error_code) { acceptNext(state); });
  });
}

}  // namespace

std::string addressKey(const asio::ip::address& address) {
  if (address.is_v4()) return address.to_string();
  const auto v6 = address.to_v6();
  if (v6.is_v4_mapped()) return asio::ip::make_address_v4(asio::ip::v4_mapped, v6).to_string();
  auto bytes = v6.to_bytes();
  for (std::size_t i = 8; i < bytes.size(); ++i) bytes[i] = 0;
  return asio::ip::address_v6(bytes).to_string() + "/64";
}

Result<std::map<std::string, std::string>> loadPage(const std::filesystem::path& root) {
  using R = Result<std::map<std::string, std::string>>;
  std::map<std::string, std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(root, ec)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || !pageFileName(name)) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) return R::fail("cannot read " + entry.path().string());
    files[name] = text.str();
  }
  if (ec) return R::fail("cannot list the page's folder " + root.string() + ": " + ec.message());
  if (!files.count("index.html")) return R::fail("no index.html in " + root.string());
  if (!files.count("three.module.js")) {
    return R::fail("no three.module.js in " + root.string() +
                   " (three.js is installed by scripts/deps.sh, then copied by the build)");
  }
  return R::ok(std::move(files));
}

std::map<std::string, std::string> loadAssets(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const char* folder : kAssetFolders) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir / folder, ec)) {
      const std::string name = entry.path().filename().string();
      if (!entry.is_regular_file() || !assetMeshName(name)) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      if (in) files[std::string("assets/") + folder + "/" + name] = text.str();
    }
  }
  return files;
}

std::vector<std::string> addThreeAddons(std::map<std::string, std::string>& files) {
  std::vector<std::string> missing;
  for (const char* name : {"OBJLoader.js", "BufferGeometryUtils.js"}) {
    const auto file = files.find(name);
    if (file == files.end()) {
      missing.push_back(name);
      continue;
    }
    // The page has no import map: its modules import three by its file name.
    std::string& code = file->second;
    for (const char* quote : {"'", "\""}) {
      const std::string bare = std::string("from ") + quote + "three" + quote;
      const std::string local = std::string("from ") + quote + "./three.module.js" + quote;
      for (std::size_t at = code.find(bare); at != std::string::npos;
           at = code.find(bare, at + local.size())) {
        code.replace(at, bare.size(), local);
      }
    }
  }
  return missing;
}

bool servedName(const std::string& name) {
  if (pageFileName(name)) return true;
  for (const char* folder : kAssetFolders) {
    const std::string prefix = std::string("assets/") + folder + "/";
    if (name.compare(0, prefix.size(), prefix) == 0)
      return assetMeshName(name.substr(prefix.size()));
  }
  return false;
}

const char* contentType(const std::string& name) {
  const auto ends = [&](const char* ext) {
    const std::string e(ext);
    return name.size() >= e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".html")) return "text/html; charset=utf-8";
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  if (ends(".json")) return "application/json";
  if (ends(".png")) return "image/png";
  if (ends(".svg")) return "image/svg+xml";
  if (ends(".obj")) return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

WebServer::WebServer(asio::io_context& io, Gateway& gateway, WebServerOptions options,
                     std::map<std::string, std::string> files)
    : state_(std::make_shared<State>(io, gateway, std::move(options), std::move(files))) {}

WebServer::~WebServer() {
  beast::error_code ignored;
  state_->acceptor.close(ignored);
}

Check<> WebServer::start() {
  beast::error_code ec;
  const auto address = asio::ip::make_address(state_->options.bind, ec);
  if (ec)
    return Check<>::refuse("bad_address", "not an IP address: '" + state_->options.bind + "'");
  const tcp::endpoint endpoint(address, state_->options.port);
  auto& acceptor = state_->acceptor;
  const auto fail = [&](const char* what) {
    return Check<>::refuse("socket_error", std::string(what) + " " + state_->options.bind + ":" +
                                               std::to_string(state_->options.port) + ": " +
                                               ec.message());
  };
  if (acceptor.open(endpoint.protocol(), ec)) return fail("cannot open a socket for");
  if (acceptor.set_option(asio::socket_base::reuse_address(true), ec)) return fail("cannot reuse");
  if (acceptor.bind(endpoint, ec)) return fail("cannot bind");
  if (acceptor.listen(asio::socket_base::max_listen_connections, ec))
    return fail("cannot listen on");
  acceptNext(state_);
  return Check<>::pass();
}

std::uint16_t WebServer::port() const {
  beast::error_code ec;
  return state_->acceptor.local_endpoint(ec).port();
}

std::uint64_t WebServer::dropped() const {
  return state_->dropped;
}

std::uint64_t WebServer::refused() const {
  return state_->refused;
}

}  // namespace pool::web
