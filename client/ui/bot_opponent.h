// A bot opponent the window starts for its player: pool-bot of a chosen level at the window's
// table, stopped with the window.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>

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
  /// Stops the bot, if one runs.
  void stop();
  /// Whether the bot started last is still running.
  bool running();

 private:
  pid_t pid_ = -1;
};

}  // namespace pool::ui
