// Which game a match plays (8-, 9-, 10-ball, three-cushion, snooker) and the one entry to its rule
// set.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/eight_ball.h"
#include "rules/game_state.h"
#include "rules/rotation.h"
#include "rules/shot.h"
#include "rules/snooker.h"
#include "rules/table_context.h"
#include "rules/three_cushion.h"
#include "rules/verdict.h"
#include "table/rack.h"

namespace pool::rules {

enum class Game : std::uint8_t { EightBall, NineBall, TenBall, ThreeCushion, Snooker };

/// What names a game and what it is played from.
struct GameInfo {
  Game game;
  const char* name;  ///< "8-ball"
  int number;        ///< 8: the number that names the game on the wire (`--game 8`)
  table::RackType rack;
  /// The table the game is played on; null: the server's pool table (`--table`).
  const char* table;
};

/// Every game, in the order players are offered them.
std::span<const GameInfo> allGames();

const char* toString(Game game);  ///< "8-ball", "9-ball", "10-ball", "three-cushion", "snooker"
/// 8, 9, 10, 3 or 22: the number that names the game on the wire (`--game 9`).
int gameNumber(Game game);
/// The game of that number; empty otherwise.
std::optional<Game> gameOfNumber(long number);
/// The game of a name ("8-ball", "three-cushion") or number ("8"); empty otherwise.
std::optional<Game> gameOfName(std::string_view name);
/// The name of the table the game is played on, or `pool_table` for a pool game.
std::string tableOf(Game game, const std::string& pool_table);
/// True for the games on pocket tables with a cue ball and object balls (8-, 9-, 10-ball).
bool isPool(Game game);
/// The rack the game is played from.
table::RackType rackTypeOf(Game game);
/// A fresh rack (a fresh game of three-cushion, its white played where it stands) for `breaker`.
GameState newRackOf(Game game, int breaker);

/// A game and its rule options.
struct GameRules {
  Game game = Game::EightBall;
  EightBallConfig eight_ball;  ///< calls and stalemate (the stalemate count serves every game)
  ThreeCushionConfig three_cushion;  ///< the points that win a game of three-cushion

  RotationConfig rotation() const;
  SnookerConfig snooker() const;
};

/// The ball the shooter strikes: the cue ball, or in three-cushion the shooter's own ball.
int cueBallFor(const GameRules& rules, const GameState& state);

/// checkIntent, checkRotationIntent, checkCaromIntent or checkSnookerIntent, by game.
Check<> checkIntentFor(const GameRules& rules, const GameState& state, const Intent& intent,
                       const std::vector<physics::Ball>& balls);

/// judgeEightBall, judgeRotation, judgeThreeCushion or judgeSnooker, by game.
Result<Verdict> judgeShot(const GameRules& rules, const GameState& state, const Shot& shot,
                          const TableContext& table);

/// applyChoice, applyRotationChoice or applySnookerChoice, by game (three-cushion offers no
/// choice: refused).
Result<Verdict> applyChoiceFor(const GameRules& rules, const GameState& state, Choice choice,
                               const std::vector<physics::Ball>& balls, const TableContext& table);

/// legalFirstBalls or rotationFirstBalls, by game; three-cushion: the red on the opening, else
/// both object balls; snooker: the balls on (every object ball with a free ball).
std::vector<int> firstBallsFor(const GameRules& rules, const GameState& state,
                               const std::vector<physics::Ball>& balls);

}  // namespace pool::rules
