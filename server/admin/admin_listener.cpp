// Unix socket, owner-only: bind, peer credentials, non-blocking line reads and replies.
#include "server/admin/admin_listener.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

#include "server/admin/admin_request.h"

namespace pool::admin {

namespace {

using Clock = std::chrono::steady_clock;

std::string errnoText(const std::string& what) {
  return what + ": " + std::strerror(errno);
}

bool fillAddress(const std::string& path, sockaddr_un& address) {
  std::memset(&address, 0, sizeof address);
  address.sun_family = AF_UNIX;
  if (path.empty() || path.size() >= sizeof address.sun_path) return false;
  std::memcpy(address.sun_path, path.c_str(), path.size());
  return true;
}

/// True when a process accepts connections on the socket at `path`.
bool answered(const sockaddr_un& address) {
  const int probe = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (probe < 0) return false;
  const bool up =
      ::connect(probe, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
  ::close(probe);
  return up;
}

}  // namespace

struct AdminListener::Connection {
  std::uint64_t id = 0;
  int fd = -1;
  Clock::time_point since;
  std::string in;
  std::string out;
  bool answered = false;  ///< a reply was queued: nothing more is read
  bool done = false;      ///< to be closed
};

Result<std::unique_ptr<AdminListener>> AdminListener::open(const std::string& path) {
  using Out = Result<std::unique_ptr<AdminListener>>;
  sockaddr_un address{};
  if (!fillAddress(path, address)) {
    return Out::fail(path + ": a socket path is 1-" + std::to_string(sizeof address.sun_path - 1) +
                     " bytes");
  }
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (!S_ISSOCK(st.st_mode)) return Out::fail(path + ": a file is there and it is not a socket");
    if (answered(address)) return Out::fail(path + ": another process answers on this socket");
    ::unlink(path.c_str());  // left by a server that is gone
  }
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return Out::fail(errnoText(path + ": socket"));
  // Owner-only from the start: no moment when another user could connect.
  const mode_t old = ::umask(0177);
  const int bound = ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  const int bind_errno = errno;
  ::umask(old);
  if (bound != 0) {
    ::close(fd);
    errno = bind_errno;
    return Out::fail(errnoText(path + ": bind"));
  }
  if (::chmod(path.c_str(), 0600) != 0 || ::listen(fd, 8) != 0) {
    const std::string why = errnoText(path);
    ::close(fd);
    ::unlink(path.c_str());
    return Out::fail(why);
  }
  return Out::ok(std::unique_ptr<AdminListener>(new AdminListener(fd, path)));
}

AdminListener::AdminListener(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}

AdminListener::~AdminListener() {
  for (auto& c : connections_) ::close(c->fd);
  ::close(fd_);
  ::unlink(path_.c_str());
}

void AdminListener::accept() {
  while (connections_.size() < kMaxConnections) {
    const int fd = ::accept4(fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;  // EAGAIN: nobody waiting
    auto c = std::make_unique<Connection>();
    c->id = next_id_++;
    c->fd = fd;
    c->since = Clock::now();
    ucred peer{};
    socklen_t size = sizeof peer;
    if (::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0 ||
        (peer.uid != ::geteuid() && peer.uid != 0)) {
      c->out = R"({"ok":false,"error":"not the server's user"})"
               "\n";
      c->answered = true;
    }
    connections_.push_back(std::move(c));
  }
}

void AdminListener::flush(Connection& c) {
  while (!c.out.empty()) {
    const ssize_t n = ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK) c.done = true;
      return;
    }
    c.out.erase(0, static_cast<std::size_t>(n));
  }
  if (c.answered) c.done = true;
}

std::vector<AdminLine> AdminListener::poll() {
  accept();
  std::vector<AdminLine> lines;
  const auto now = Clock::now();
  for (auto& c : connections_) {
    if (!c->answered) {
      char buffer[4096];
      for (;;) {
        const ssize_t n = ::recv(c->fd, buffer, sizeof buffer, 0);
        if (n > 0) {
          c->in.append(buffer, static_cast<std::size_t>(n));
          if (c->in.size() > kMaxRequestBytes + 1) break;
          continue;
        }
        if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) c->done = true;  // hung up
        break;
      }
      const auto end = c->in.find('\n');
      if (end != std::string::npos && end <= kMaxRequestBytes) {
        lines.push_back({c->id, c->in.substr(0, end)});
        c->answered = true;  // the reply comes through reply()
        c->done = false;     // a client may shut its writing half down and wait for the answer
      } else if (end != std::string::npos || c->in.size() > kMaxRequestBytes) {
        c->out = R"({"ok":false,"error":"request longer than 8192 bytes"})"
                 "\n";
        c->answered = true;
        c->done = false;
      }
    }
    if (!c->out.empty()) flush(*c);
    if (now - c->since > kIdle) c->done = true;
  }
  std::erase_if(connections_, [](const auto& c) {
    if (c->done) ::close(c->fd);
    return c->done;
  });
  return lines;
}

void AdminListener::reply(std::uint64_t connection, const std::string& reply) {
  for (auto& c : connections_) {
    if (c->id != connection) continue;
    c->out = reply + "\n";
    flush(*c);
    if (c->done) {
      ::close(c->fd);
      std::erase_if(connections_, [&](const auto& other) { return other->id == connection; });
    }
    return;
  }
}

}  // namespace pool::admin
