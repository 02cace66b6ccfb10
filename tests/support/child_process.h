// Real processes for the client integration tests: pool-server, pool-bot and pool-client run as
// children on the test's DDS domain, their output in files, killed and reaped in teardown.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace pool::client::test {

using namespace std::chrono_literals;

/// Points this process (and the children it starts) at the loopback-only Cyclone configuration.
inline void useLoopbackConfig() {
  const std::string uri = std::string("file://") + POOL_SOURCE_DIR + "/assets/cyclone-lo.xml";
  ::setenv("CYCLONEDDS_URI", uri.c_str(), 1);
}

/// A scratch folder for one test's files, removed afterwards.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) {
    std::string pattern = "/tmp/pool-client-test-" + tag + "-XXXXXX";
    path_ = ::mkdtemp(pattern.data()) ? pattern : "/tmp";
  }
  ~ScratchDir() {
    if (path_ != "/tmp" && !::getenv("POOL_KEEP_TEST_FILES")) {
      std::system(("rm -rf '" + path_ + "'").c_str());
    }
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

/// One of the build's executables as a child process, stdout and stderr each to a file.
/// Started by the constructor; SIGKILLed (if still running) and reaped by the destructor.
class ChildProcess {
 public:
  ChildProcess(const std::string& program, const std::vector<std::string>& args,
               std::string out_path, std::string err_path)
      : out_path_(std::move(out_path)), err_path_(std::move(err_path)) {
    std::vector<std::string> argv{std::string(POOL_BIN_DIR) + "/" + program};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> raw;
    for (auto& a : argv) raw.push_back(a.data());
    raw.push_back(nullptr);
    // Everything the child needs is prepared before the fork: it only opens, dups and execs.
    pid_ = ::fork();
    if (pid_ == 0) {
      redirect(out_path_.c_str(), 1);
      redirect(err_path_.c_str(), 2);
      ::execv(raw[0], raw.data());
      ::_exit(127);
    }
  }
  ~ChildProcess() { kill(SIGKILL); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Sends `sig` and, for SIGKILL, reaps the child.
  void kill(int sig) {
    if (pid_ <= 0 || exit_code_) return;
    ::kill(pid_, sig);
    if (sig == SIGKILL) {
      int status = 0;
      ::waitpid(pid_, &status, 0);
      exit_code_ = -1;
    }
  }

  /// Waits up to `timeout` for the child to end: its exit code (-1: ended by a signal), or empty
  /// while it still runs.
  std::optional<int> waitExit(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    do {
      if (exit_code_) return exit_code_;
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        return exit_code_;
      }
      std::this_thread::sleep_for(10ms);
    } while (std::chrono::steady_clock::now() < deadline);
    return std::nullopt;
  }

  bool running() { return !waitExit(0ms); }
  pid_t pid() const { return pid_; }
  std::string out() const { return slurp(out_path_); }
  std::string err() const { return slurp(err_path_); }
  /// The last non-empty line of stdout.
  std::string lastLine() const {
    std::istringstream in(out());
    std::string line, last;
    while (std::getline(in, line)) {
      if (!line.empty()) last = line;
    }
    return last;
  }

 private:
  static void redirect(const char* path, int fd) {
    const int file = ::open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (file >= 0) {
      ::dup2(file, fd);
      ::close(file);
    }
  }
  static std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::string out_path_;
  std::string err_path_;
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
};

}  // namespace pool::client::test
