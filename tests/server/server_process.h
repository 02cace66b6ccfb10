// Runs the real pool-server as a child process on its own DDS domain, and ends it in teardown.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace pool::server::test {

/// The loopback-only Cyclone configuration of the source tree, as a CYCLONEDDS_URI value.
inline std::string loopbackUri() {
  return std::string("file://") + POOL_SOURCE_DIR + "/assets/cyclone-lo.xml";
}

/// Points this process's participants at the loopback configuration.
inline void useLoopbackConfig() {
  ::setenv("CYCLONEDDS_URI", loopbackUri().c_str(), 1);
}

/// A pool-server child process: started in the constructor, killed (if still running) and reaped
/// in the destructor. Its stdout and stderr go to a log file, shown by log().
class ServerProcess {
 public:
  ServerProcess(std::uint32_t domain, const std::vector<std::string>& args)
      : log_path_("/tmp/pool-server-test-" + std::to_string(domain) + "-" +
                  std::to_string(::getpid()) + ".log") {
    std::vector<std::string> argv{std::string(POOL_BIN_DIR) + "/pool-server", "--domain",
                                  std::to_string(domain)};
    argv.insert(argv.end(), args.begin(), args.end());
    pid_ = ::fork();
    if (pid_ == 0) execChild(argv);
  }
  ~ServerProcess() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    std::remove(log_path_.c_str());
    std::system(("rm -rf '" + data_home_ + "'").c_str());
  }
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int sig) const { ::kill(pid_, sig); }

  /// Waits up to `timeout` for the child to end: its exit code, -1 if a signal ended it, or
  /// empty when it is still running.
  std::optional<int> waitExit(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return std::nullopt;
  }

  /// Everything the server logged so far.
  std::string log() const {
    std::ifstream in(log_path_);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  [[noreturn]] void execChild(const std::vector<std::string>& argv) const {
    const int fd = ::creat(log_path_.c_str(), 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    ::setenv("CYCLONEDDS_URI", loopbackUri().c_str(), 1);
    // Its default database goes to a scratch folder, never the real home.
    ::setenv("XDG_DATA_HOME", data_home_.c_str(), 1);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }

  std::string log_path_;
  std::string data_home_ = log_path_ + ".data";
  pid_t pid_ = -1;
  bool exited_ = false;
};

/// The resident memory of process `pid` in MB (0 when unreadable).
inline double residentMb(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

}  // namespace pool::server::test
