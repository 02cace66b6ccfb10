// Connect, write the line, wait (poll) for the reply line.
#include "server/admin/admin_call.h"

#include <errno.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>

namespace pool::admin {

namespace {

using Clock = std::chrono::steady_clock;

/// Closes the descriptor when the call returns.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

Result<std::string> call(const std::string& socket_path, const std::string& request,
                         std::chrono::milliseconds timeout) {
  using Out = Result<std::string>;
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (socket_path.empty() || socket_path.size() >= sizeof address.sun_path) {
    return Out::fail(socket_path + ": not a usable socket path");
  }
  std::memcpy(address.sun_path, socket_path.c_str(), socket_path.size());
  Fd s{::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0)};
  if (s.fd < 0) return Out::fail(std::string("socket: ") + std::strerror(errno));
  if (::connect(s.fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int e = errno;
    std::string why = socket_path + ": " + std::strerror(e);
    if (e == ENOENT || e == ECONNREFUSED) why += " (is pool-server running with this database?)";
    if (e == EACCES) why += " (run as the server's user or root)";
    return Out::fail(why);
  }
  const std::string line = request + "\n";
  std::size_t sent = 0;
  while (sent < line.size()) {
    const ssize_t n = ::send(s.fd, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0) return Out::fail(std::string("send: ") + std::strerror(errno));
    sent += static_cast<std::size_t>(n);
  }
  const auto deadline = Clock::now() + timeout;
  std::string reply;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return Out::fail("no reply from the server within the timeout");
    pollfd p{s.fd, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left)) < 0 && errno != EINTR) {
      return Out::fail(std::string("poll: ") + std::strerror(errno));
    }
    char buffer[4096];
    const ssize_t n = ::recv(s.fd, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n > 0) {
      reply.append(buffer, static_cast<std::size_t>(n));
      if (const auto end = reply.find('\n'); end != std::string::npos)
        return Out::ok(reply.substr(0, end));
      continue;
    }
    if (n == 0) return Out::fail("the server closed the connection without a reply");
    if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      return Out::fail(std::string("recv: ") + std::strerror(errno));
    }
  }
}

}  // namespace pool::admin
