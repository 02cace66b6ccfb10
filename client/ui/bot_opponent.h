// A bot opponent the window starts for its player: pool-bot of a chosen level at the window's
// table, stopped with the window.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "client/bot/ai/bot_level.h"
#include "core/check.h"

namespace pool::ui {

/// The name a bot of `level` plays under ("Pro bot").
std::string botOpponentName(bot::Level level);

/// One pool-bot process: started beside this program's executable (else found on the PATH),
/// playing rematches while the window stays, stopped (SIGTERM, then SIGKILL) when the window
/// closes or another is started.
class BotOpponent {
 public:
  BotOpponent() = default;
  ~BotOpponent() { stop(); }
  BotOpponent(const BotOpponent&) = delete;
  BotOpponent& operator=(const BotOpponent&) = delete;

  /// Starts a bot of `level` to take the free seat of `match` on DDS `domain`, or refuses with why
  /// it could not start, in one line.
  Check<> start(std::uint32_t domain, const std::string& match, bot::Level level);
  /// Starts a bot of `level` named `name` that enters tournament `tournament` and plays each of
  /// its matches there (pool-bot --tournament), or refuses with why, in one line.
  Check<> enter(std::uint32_t domain, const std::string& tournament, bot::Level level,
                const std::string& name);
  /// Stops the bot, if one runs.
  void stop();
  /// Whether the bot started last is still running.
  bool running();

 private:
  /// Starts pool-bot with `args` (after the program's path), its output to /dev/null.
  Check<> launch(std::vector<std::string> args);

  pid_t pid_ = -1;
};

}  // namespace pool::ui
