// A player in a process of its own, so a test can kill it with SIGKILL like a crashed client.
#pragma once

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

#include "server_fixture.h"

namespace pool::server::test {

inline constexpr const char* kPlayerDomainEnv = "POOL_SERVER_TEST_PLAYER_DOMAIN";
inline constexpr const char* kPlayerKeyEnv = "POOL_SERVER_TEST_PLAYER_KEY";

/// In the re-executed test binary: take seat 1 of "t-1" as "Bob" with the key kept in the file
/// $POOL_SERVER_TEST_PLAYER_KEY, write the token on stdout as one line, then wait to be killed.
/// Returns an exit code on failure.
inline int playUntilKilled(std::uint32_t domain) {
  TestClient bob(domain, "bob-process");
  const char* key_file = std::getenv(kPlayerKeyEnv);
  const auto key =
      key_file ? protocol::loadOrCreateKeyFile(key_file) : Result<protocol::KeyPair>::fail("");
  if (!key) return 5;
  bob.useKey(*key);
  if (!bob.waitForServer()) return 3;
  const auto reply = bob.join(pool_JOIN_SEAT, "t-1", "Bob", 1);
  if (!reply || reply->outcome != pool_JOIN_ACCEPTED) return 4;
  std::printf("%llu\n", static_cast<unsigned long long>(reply->seat_token));
  std::fflush(stdout);
  for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
}

/// A player process: the test binary re-executed (a fresh process with no DDS state), playing
/// playUntilKilled. Killed and reaped when it goes out of scope.
class KillablePlayer {
 public:
  explicit KillablePlayer(std::uint32_t domain)
      : key_file_(
            std::filesystem::temp_directory_path() /
            ("pool-player-" + std::to_string(::getpid()) + "-" + std::to_string(domain) + ".key")) {
    std::filesystem::remove(key_file_);
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(fds[1], 1);
      ::close(fds[0]);
      ::close(fds[1]);
      ::setenv(kPlayerDomainEnv, std::to_string(domain).c_str(), 1);
      ::setenv(kPlayerKeyEnv, key_file_.c_str(), 1);
      ::execl("/proc/self/exe", "server_tests_player", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    out_ = fds[0];
  }
  ~KillablePlayer() {
    kill();
    if (out_ >= 0) ::close(out_);
    std::error_code ec;
    std::filesystem::remove(key_file_, ec);
  }
  KillablePlayer(const KillablePlayer&) = delete;
  KillablePlayer& operator=(const KillablePlayer&) = delete;

  /// The seat token the player printed, waiting up to `timeout` for it.
  std::optional<std::uint64_t> token(std::chrono::milliseconds timeout) {
    std::string line;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (line.find('\n') == std::string::npos && std::chrono::steady_clock::now() < deadline) {
      pollfd p{out_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      char buffer[64];
      const ssize_t n = ::read(out_, buffer, sizeof buffer);
      if (n <= 0) break;
      line.append(buffer, static_cast<std::size_t>(n));
    }
    if (line.find('\n') == std::string::npos) return std::nullopt;
    return std::stoull(line);
  }

  /// The key pair the player kept in its key file (once it has taken its seat).
  Result<protocol::KeyPair> key() const { return protocol::loadOrCreateKeyFile(key_file_); }

  /// SIGKILL: no goodbye on the wire, only the liveliness lease running out.
  void kill() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  std::filesystem::path key_file_;
  pid_t pid_ = -1;
  int out_ = -1;
};

}  // namespace pool::server::test
