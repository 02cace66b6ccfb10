// Runs a program as a child process in a given folder; captures stdout, stderr, exit code apart.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <string>
#include <vector>

namespace pool::scenario::testing {

/// What a finished child process left behind.
struct ProcessResult {
  int exit_code = -1;  ///< the exit status, or -1 if it did not exit normally
  std::string out;     ///< everything written to stdout
  std::string err;     ///< everything written to stderr
};

namespace detail {

// In the child: wire the pipes to fds 0-2, change directory, exec. Never returns.
[[noreturn]] inline void execChild(const std::vector<std::string>& argv, const std::string& cwd,
                                   const std::array<int, 2>& in, const std::array<int, 2>& out,
                                   const std::array<int, 2>& err) {
  dup2(in[0], 0);
  dup2(out[1], 1);
  dup2(err[1], 2);
  for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) close(fd);
  if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(127);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  execv(args[0], args.data());
  _exit(127);
}

// Feeds stdin and drains stdout and stderr together, so no pipe fills up and blocks the child.
inline void pump(int in_fd, int out_fd, int err_fd, const std::string& input, ProcessResult& r) {
  std::size_t written = 0;
  if (input.empty()) {
    close(in_fd);
    in_fd = -1;
  }
  std::array<char, 4096> buf{};
  while (out_fd >= 0 || err_fd >= 0) {
    std::array<pollfd, 3> fds = {pollfd{in_fd, POLLOUT, 0}, pollfd{out_fd, POLLIN, 0},
                                 pollfd{err_fd, POLLIN, 0}};
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    if (in_fd >= 0 && (fds[0].revents & (POLLOUT | POLLERR | POLLHUP)) != 0) {
      const ssize_t n = write(in_fd, input.data() + written, input.size() - written);
      if (n > 0) written += static_cast<std::size_t>(n);
      if (n <= 0 || written == input.size()) {
        close(in_fd);
        in_fd = -1;
      }
    }
    for (int k = 1; k <= 2; ++k) {
      int& fd = k == 1 ? out_fd : err_fd;
      if (fd < 0 || (fds[static_cast<std::size_t>(k)].revents & (POLLIN | POLLHUP | POLLERR)) == 0)
        continue;
      const ssize_t n = read(fd, buf.data(), buf.size());
      if (n > 0) {
        (k == 1 ? r.out : r.err).append(buf.data(), static_cast<std::size_t>(n));
      } else {
        close(fd);
        fd = -1;
      }
    }
  }
  if (in_fd >= 0) close(in_fd);
}

}  // namespace detail

/// Runs argv[0] (a path) with the given arguments in `cwd`, writing `input` to its stdin.
inline ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& input = "",
                                const std::string& cwd = "/tmp") {
  std::array<int, 2> in{}, out{}, err{};
  ProcessResult r;
  if (pipe(in.data()) != 0 || pipe(out.data()) != 0 || pipe(err.data()) != 0) return r;
  const pid_t pid = fork();
  if (pid == 0) detail::execChild(argv, cwd, in, out, err);
  close(in[0]);
  close(out[1]);
  close(err[1]);
  signal(SIGPIPE,
         SIG_IGN);  // a child that exits before reading all of stdin must not kill the test
  detail::pump(in[1], out[0], err[0], input, r);
  int status = 0;
  waitpid(pid, &status, 0);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace pool::scenario::testing
