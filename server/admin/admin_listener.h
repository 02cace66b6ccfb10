// The server's end of the admin channel: a Unix socket only the server's own user (or root) may
// use, read without ever blocking the server's loop.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"

namespace pool::admin {

/// One request line received on a connection.
struct AdminLine {
  std::uint64_t connection = 0;
  std::string line;
};

/// Listens on a Unix socket at `path`. The socket is made owner-only (0600) and every connection's
/// peer credentials are checked: another user's process (root aside) is answered with an error and
/// dropped. Each connection carries one request line and receives one reply line. Non-blocking
/// throughout: a client that sends nothing, too much, or does not read its reply is dropped after
/// kIdle.
class AdminListener {
 public:
  /// Binds `path`: a socket left by a server that is gone is replaced; a file that is not a socket,
  /// or a socket another process answers on, is refused. The reason is one line.
  static Result<std::unique_ptr<AdminListener>> open(const std::string& path);
  ~AdminListener();
  AdminListener(const AdminListener&) = delete;
  AdminListener& operator=(const AdminListener&) = delete;

  /// Accepts waiting connections and reads what arrived; the complete request lines. Never blocks.
  std::vector<AdminLine> poll();
  /// Sends `reply` (one line; a newline is added) on `connection`, then closes it once written.
  void reply(std::uint64_t connection, const std::string& reply);

  /// The socket's file descriptor (to wait on it).
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }

  /// How long a connection may sit before it is dropped.
  static constexpr std::chrono::seconds kIdle{5};
  /// Connections held at once; more wait in the listen queue.
  static constexpr std::size_t kMaxConnections = 16;

 private:
  struct Connection;
  AdminListener(int fd, std::string path);
  void accept();
  void flush(Connection& c);

  int fd_;
  std::string path_;
  std::uint64_t next_id_ = 1;
  std::vector<std::unique_ptr<Connection>> connections_;
};

}  // namespace pool::admin
