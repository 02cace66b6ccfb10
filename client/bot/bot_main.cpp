// pool-bot: a headless player that takes a seat and plays one match to its end.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "client/bot/bot_player.h"
#include "client/net/game_client.h"
#include "core/text.h"
#include "net/dds_error.h"

namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) {
  g_stop = true;
}

struct Flags {
  std::uint32_t domain = 0;
  std::string name;
  std::string log_level = "info";
  double timeout = 0.0;  // s; 0: none
  pool::bot::BotConfig bot;
  // How to play a table the bot opens (the first player at a table chooses); unset: the server's.
  int game = 0;
  int race = 1;
  std::string breaks = "alternate";
  double shot_clock = 0.0;
};

// The table settings the flags ask for, or why they are refused; empty without --game.
std::optional<pool::protocol::MatchSettings> tableSettings(const Flags& flags, std::string& why) {
  if (flags.game == 0) return std::nullopt;
  pool::protocol::MatchSettings s;
  const auto game = pool::rules::gameOfNumber(flags.game);
  const auto breaks = pool::protocol::breakOrderOf(flags.breaks);
  if (!game) why = "--game: must be 8, 9 or 10";
  if (!breaks) why = "--breaks: must be alternate or winner";
  if (!game || !breaks) return std::nullopt;
  s.game = *game;
  s.race_to = flags.race;
  s.breaks = *breaks;
  s.shot_clock = flags.shot_clock;
  if (auto reason = pool::protocol::checkSettings(s); !reason) why = reason.error();
  return s;
}

int run(const Flags& flags) {
  using namespace pool;
  std::optional<client::SeatRecord> saved;
  if (!flags.bot.seat_file.empty()) {
    auto read = client::readSeatFile(flags.bot.seat_file);
    if (!read) spdlog::warn("ignoring seat file: {}", read.error());
    if (read && *read) saved = **read;
  }
  // The key its commands are signed with lives beside the seat file: a restarted bot rejoins
  // its seat with the same key.
  std::optional<protocol::KeyPair> key;
  if (!flags.bot.seat_file.empty()) {
    auto loaded = protocol::loadOrCreateKeyFile(client::keyFileFor(flags.bot.seat_file));
    if (!loaded) {
      spdlog::error("key file: {}", loaded.error());
      return 2;
    }
    key = *loaded;
  }
  std::string why;
  const auto settings = tableSettings(flags, why);
  if (!why.empty()) {
    spdlog::error("{}", why);
    return 2;
  }
  // Server keys are pinned in memory for the bot's run (a restarted bot pins again).
  client::ClientOptions options{
      flags.domain, "", flags.name, {}, [](const std::string& line, bool problem) {
        if (problem) {
          spdlog::warn("{}", line);
        } else {
          spdlog::info("{}", line);
        }
      }};
  client::GameClient client(std::move(options), key);
  client.setTableSettings(settings);
  bot::BotPlayer player(client, flags.bot, saved);
  const auto start = std::chrono::steady_clock::now();
  auto now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  spdlog::info("{} on domain {} as client {}{}", flags.name, flags.domain, client.clientId(),
               saved ? " (rejoining " + saved->match + ")" : std::string());
  while (!player.done() && !g_stop) {
    if (flags.timeout > 0 && now() > flags.timeout) {
      spdlog::error("gave up after {} s ({})", flags.timeout, bot::toString(player.stage()));
      return 3;
    }
    client.wait(std::chrono::milliseconds(20));
    player.step(now());
  }
  if (player.stage() == bot::BotStage::Failed) {
    spdlog::error("{}", player.failure());
    return 2;
  }
  if (g_stop) return 130;
  std::cout << player.resultLine() << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Flags flags;
  CLI::App app{"pool-bot: a headless 8-, 9- and 10-ball player"};
  app.add_option("--domain", flags.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--match", flags.bot.match,
                 "match id to sit in (default: the lowest-numbered with a free seat)");
  app.add_option("--name", flags.name, "player name")->required();
  std::string level = pool::bot::toString(pool::bot::kDefaultLevel);
  auto* level_option =
      app.add_option("--level", level,
                     "beginner, club, league or pro: its stroke's error and how it plans "
                     "(default club; pro plays under the computer olympiad's noise)")
          ->check(CLI::IsMember({"beginner", "club", "league", "pro"}));
  app.add_option("--skill", flags.bot.skill,
                 "0..1 instead of a level: aim and speed error only (1 = none), exact planning")
      ->check(CLI::Range(0.0, 1.0))
      ->excludes(level_option);
  app.add_option("--seed", flags.bot.seed, "seed of the execution noise");
  app.add_option("--token-file", flags.bot.seat_file,
                 "file keeping the seat token: read at start to rejoin, written when seated "
                 "(the signing key is kept beside it, in FILE.key)");
  app.add_flag("--ignore-shot-clock", flags.bot.ignore_shot_clock,
               "think the full --think even past the shot clock (tests)");
  app.add_option("--concede-from-rack", flags.bot.concede_from_rack,
                 "concede every rack from this one on, on the bot's first turn in it (tests)");
  app.add_option("--game", flags.game, "a table the bot opens: 8, 9 or 10 (default: the server's)");
  app.add_option("--race", flags.race, "with --game: racks to win (1-15)");
  app.add_option("--breaks", flags.breaks, "with --game: alternate or winner");
  app.add_option("--shot-clock", flags.shot_clock, "with --game: seconds per shot, 0: none");
  app.add_flag("--stay", flags.bot.stay,
               "at game over ask for a rematch and stay while the opponent keeps their seat");
  app.add_option("--think", flags.bot.think, "seconds to wait on each turn before shooting")
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--timeout", flags.timeout, "give up (exit 3) after this many seconds; 0: never");
  app.add_option("--log-level", flags.log_level, "trace, debug, info, warn, error, off");
  CLI11_PARSE(app, argc, argv);
  flags.bot.level = *pool::bot::levelFromString(level);

  // Logs go to stderr: stdout carries only the result line.
  spdlog::set_default_logger(spdlog::stderr_color_mt("pool-bot"));
  spdlog::set_level(spdlog::level::from_str(flags.log_level));
  if (!pool::isCleanUtf8(flags.name, 31)) {
    std::cerr << "--name: 1-31 bytes of UTF-8 without control characters\n";
    return 2;
  }
  if (spdlog::level::from_str(flags.log_level) == spdlog::level::off && flags.log_level != "off") {
    std::cerr << "--log-level: '" << flags.log_level
              << "' is not one of trace, debug, info, warn, error, critical, off\n";
    return 2;
  }
  // The name goes into the log pattern: a '%' in it must not be read as a pattern flag.
  std::string name;
  for (char ch : flags.name) name += ch == '%' ? std::string("%%") : std::string(1, ch);
  spdlog::set_pattern("[%H:%M:%S.%e] [" + name + "] [%l] %v");
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  try {
    return run(flags);
  } catch (const pool::net::DdsError& e) {
    spdlog::error("DDS: {}", e.what());
    return 1;
  }
}
