// Starting and stopping the window's bot opponent (a pool-bot child that dies with the window).
#include "client/ui/bot_opponent.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>
#include <vector>

#include "core/program_dir.h"

namespace pool::ui {
namespace {

// pool-bot beside this executable (the build's bin/ or /usr/bin), else the first on the PATH;
// empty when there is none.
std::string botProgram() {
  std::error_code ec;
  if (const auto bin = programDir()) {
    const auto beside = *bin / "pool-bot";
    if (std::filesystem::is_regular_file(beside, ec)) return beside.string();
  }
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t at = 0; at <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', at), dirs.size());
    const auto candidate = std::filesystem::path(dirs.substr(at, end - at)) / "pool-bot";
    if (end > at && access(candidate.c_str(), X_OK) == 0) return candidate.string();
    at = end + 1;
  }
  return "";
}

}  // namespace

std::string botOpponentName(bot::Level level) {
  std::string name = bot::toString(level);
  if (!name.empty()) name[0] = static_cast<char>(name[0] - 'a' + 'A');
  return name + " bot";
}

Check<> BotOpponent::start(std::uint32_t domain, const std::string& match, bot::Level level) {
  // --stay: it plays the rematches the player asks for; its log is the player's only when it
  // warns (a window's terminal is not the bot's log).
  return launch({"--domain", std::to_string(domain), "--match", match, "--level",
                 bot::toString(level), "--name", botOpponentName(level), "--think", "0.8", "--stay",
                 "--log-level", "warn"});
}

Check<> BotOpponent::enter(std::uint32_t domain, const std::string& tournament, bot::Level level,
                           const std::string& name) {
  return launch({"--domain", std::to_string(domain), "--tournament", tournament, "--level",
                 bot::toString(level), "--name", name, "--think", "0.8", "--log-level", "warn"});
}

Check<> BotOpponent::launch(std::vector<std::string> args) {
  stop();
  const std::string program = botProgram();
  if (program.empty())
    return Check<>::refuse(
        "no_program", "could not start the bot: no pool-bot beside pool-client or on the PATH");
  args.insert(args.begin(), program);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    return Check<>::refuse("fork_failed",
                           std::string("could not start pool-bot: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // The child: only async-signal-safe calls until exec. It is sent SIGTERM when the window dies,
    // however it dies (the bot leaves its seat on SIGTERM), so no bot outlives its window.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(1);
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, STDOUT_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  pid_ = pid;
  return Check<>::pass();
}

bool BotOpponent::running() {
  if (pid_ <= 0) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    pid_ = -1;
    return false;
  }
  return true;
}

void BotOpponent::stop() {
  if (!running()) return;
  kill(pid_, SIGTERM);
  // A bot leaves its seat and exits within a few frames of SIGTERM; one that does not is killed.
  for (int i = 0; i < 40; ++i) {
    if (!running()) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  pid_ = -1;
}

}  // namespace pool::ui
