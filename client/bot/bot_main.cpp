// pool-bot: a headless player that takes a seat and plays one match to its end.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "client/bot/ai/bot_level.h"
#include "client/bot/bot_player.h"
#include "client/bot/tournament_entrant.h"
#include "client/net/game_client.h"
#include "core/check.h"
#include "core/result.h"
#include "core/text.h"
#include "net/dds_error.h"

namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) {
  g_stop = true;
}

/// What pool-bot's flags ask for, each flag bound to its field (addBotFlags).
struct BotProgramConfig {
  std::uint32_t domain = 0;
  std::string name;
  std::string level = pool::bot::toString(pool::bot::kDefaultLevel);  // read into bot.level
  std::string log_level = "info";
  double timeout = 0.0;  // s; 0: none
  pool::bot::BotConfig bot;
  std::string tournament;  // a tournament to enter and play through
  // How to play a table the bot opens (the first player at a table chooses); unset: the server's.
  std::string game;  ///< empty: the server's
  int race = 1;
  int points = pool::protocol::kDefaultPoints;
  std::string breaks = "alternate";
  double shot_clock = 0.0;
};

/// Every flag of pool-bot, each bound to its field of `c`.
void addBotFlags(CLI::App& app, BotProgramConfig& c) {
  app.add_option("--domain", c.domain, "DDS domain id")->check(CLI::Range(0, 232));
  auto* match = app.add_option(
      "--match", c.bot.match, "match id to sit in (default: the lowest-numbered with a free seat)");
  app.add_option("--tournament", c.tournament,
                 "enter this tournament (its id, e.g. srv-t1) and play each match it gives the "
                 "bot until it is over")
      ->excludes(match);
  app.add_option("--name", c.name, "player name")->required();
  auto* level = app.add_option("--level", c.level,
                               "beginner, club, league or pro: its stroke's error and how it plans "
                               "(default club; pro plays under the computer olympiad's noise)")
                    ->check(CLI::IsMember(pool::bot::levelNames()));
  app.add_option("--skill", c.bot.skill,
                 "0..1 instead of a level: aim and speed error only (1 = none), exact planning")
      ->check(CLI::Range(0.0, 1.0))
      ->excludes(level);
  app.add_option("--seed", c.bot.seed, "seed of the execution noise");
  app.add_option("--token-file", c.bot.seat_file,
                 "file keeping the seat token: read at start to rejoin, written when seated "
                 "(the signing key is kept beside it, in FILE.key)");
  app.add_flag("--ignore-shot-clock", c.bot.ignore_shot_clock,
               "think the full --think even past the shot clock (tests)");
  app.add_option("--concede-from-rack", c.bot.concede_from_rack,
                 "concede every rack from this one on, on the bot's first turn in it (tests)");
  app.add_option(
      "--game", c.game,
      "a table the bot opens: 8, 9, 10, three-cushion or snooker (default: the server's)");
  app.add_option("--points", c.points, "with --game three-cushion: points that win a game (1-100)");
  app.add_option("--race", c.race, "with --game: racks to win (1-15)");
  app.add_option("--breaks", c.breaks, "with --game: alternate or winner");
  app.add_option("--shot-clock", c.shot_clock, "with --game: seconds per shot, 0: none");
  app.add_flag("--stay", c.bot.stay,
               "at game over ask for a rematch and stay while the opponent keeps their seat");
  app.add_option("--think", c.bot.think, "seconds to wait on each turn before shooting")
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--timeout", c.timeout, "give up (exit 3) after this many seconds; 0: never");
  app.add_option("--log-level", c.log_level, "trace, debug, info, warn, error, off");
}

// The table settings the flags ask for (none without --game), or why they are refused.
pool::Result<std::optional<pool::protocol::MatchSettings>> tableSettings(
    const BotProgramConfig& c) {
  using R = pool::Result<std::optional<pool::protocol::MatchSettings>>;
  if (c.game.empty()) return R::ok(std::nullopt);
  pool::protocol::MatchSettings s;
  const auto game = pool::rules::gameOfName(c.game);
  const auto breaks = pool::protocol::breakOrderOf(c.breaks);
  if (!breaks) return R::fail("bad_breaks", "--breaks: must be alternate or winner");
  if (!game) return R::fail("bad_game", "--game: must be 8, 9, 10, three-cushion or snooker");
  s.game = *game;
  if (s.game == pool::rules::Game::ThreeCushion) s.points = c.points;
  s.race_to = c.race;
  s.breaks = *breaks;
  s.shot_clock = c.shot_clock;
  if (auto ok = pool::protocol::checkSettings(s); !ok) return R::fail(ok.code(), ok.error());
  return R::ok(s);
}

int run(const BotProgramConfig& c) {
  using namespace pool;
  std::optional<client::SeatRecord> saved;
  if (!c.bot.seat_file.empty()) {
    auto read = client::readSeatFile(c.bot.seat_file);
    if (!read) spdlog::warn("ignoring seat file: {}", read.error());
    if (read && *read) saved = **read;
  }
  // The key its commands are signed with lives beside the seat file: a restarted bot rejoins
  // its seat with the same key.
  std::optional<protocol::KeyPair> key;
  if (!c.bot.seat_file.empty()) {
    auto loaded = protocol::loadOrCreateKeyFile(client::keyFileFor(c.bot.seat_file));
    if (!loaded) {
      spdlog::error("key file: {}", loaded.error());
      return 2;
    }
    key = *loaded;
  }
  const auto table = tableSettings(c);
  if (!table) {
    spdlog::error("{}", table.error());
    return 2;
  }
  const auto& settings = *table;
  // Server keys are pinned in memory for the bot's run (a restarted bot pins again).
  client::ClientOptions options{
      c.domain, "", c.name, {}, [](const std::string& line, bool problem) {
        if (problem) {
          spdlog::warn("{}", line);
        } else {
          spdlog::info("{}", line);
        }
      }};
  client::GameClient client(std::move(options), key);
  client.setTableSettings(settings);
  const auto start = std::chrono::steady_clock::now();
  auto now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  if (!c.tournament.empty()) {
    bot::TournamentEntrant entrant(client, c.bot, c.tournament);
    spdlog::info("{} on domain {} as client {}: entering {}", c.name, c.domain, client.clientId(),
                 c.tournament);
    while (!entrant.done() && !g_stop) {
      if (c.timeout > 0 && now() > c.timeout) {
        spdlog::error("gave up after {} s in {}", c.timeout, c.tournament);
        return 3;
      }
      client.wait(std::chrono::milliseconds(20));
      entrant.step(now());
    }
    if (entrant.failed()) {
      spdlog::error("{}", entrant.failure());
      return 2;
    }
    if (g_stop) return 130;
    std::cout << entrant.resultLine() << std::endl;
    return 0;
  }
  bot::BotPlayer player(client, c.bot, saved);
  spdlog::info("{} on domain {} as client {}{}", c.name, c.domain, client.clientId(),
               saved ? " (rejoining " + saved->match + ")" : std::string());
  while (!player.done() && !g_stop) {
    if (c.timeout > 0 && now() > c.timeout) {
      spdlog::error("gave up after {} s ({})", c.timeout, bot::toString(player.stage()));
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

/// Logs go to stderr (stdout carries only the result line) at `c.log_level`; the lines name the
/// bot. Refuses a name or a level it cannot take, with why.
pool::Check<> startLogging(const BotProgramConfig& c) {
  spdlog::set_default_logger(spdlog::stderr_color_mt("pool-bot"));
  spdlog::set_level(spdlog::level::from_str(c.log_level));
  if (!pool::isCleanUtf8(c.name, 31)) {
    return pool::Check<>::refuse("bad_name",
                                 "--name: 1-31 bytes of UTF-8 without control characters");
  }
  if (spdlog::level::from_str(c.log_level) == spdlog::level::off && c.log_level != "off") {
    return pool::Check<>::refuse(
        "bad_log_level", "--log-level: '" + c.log_level +
                             "' is not one of trace, debug, info, warn, error, critical, off");
  }
  // The name goes into the log pattern: a '%' in it must not be read as a pattern flag.
  std::string name;
  for (char ch : c.name) name += ch == '%' ? std::string("%%") : std::string(1, ch);
  spdlog::set_pattern("[%H:%M:%S.%e] [" + name + "] [%l] %v");
  return pool::Check<>::pass();
}

}  // namespace

int main(int argc, char** argv) {
  BotProgramConfig config;
  CLI::App app{"pool-bot: a headless 8-, 9- and 10-ball player"};
  addBotFlags(app, config);
  CLI11_PARSE(app, argc, argv);
  config.bot.level = *pool::bot::levelFromString(config.level);
  if (auto ok = startLogging(config); !ok) {
    std::cerr << ok.error() << '\n';
    return 2;
  }
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  try {
    return run(config);
  } catch (const pool::net::DdsError& e) {
    spdlog::error("DDS: {}", e.what());
    return 1;
  }
}
