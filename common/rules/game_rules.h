// Which game a match plays (8-, 9- or 10-ball) and the one entry to its rule set.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/eight_ball.h"
#include "rules/game_state.h"
#include "rules/rotation.h"
#include "rules/shot.h"
#include "rules/table_context.h"
#include "rules/verdict.h"
#include "table/rack.h"

namespace pool::rules {

enum class Game : std::uint8_t { EightBall, NineBall, TenBall };

/// What names a game and what it is played from.
struct GameInfo {
  Game game;
  const char* name;  ///< "8-ball"
  int number;        ///< 8: the number that names the game (`--game 8`)
  table::RackType rack;
};

/// Every game, in the order players are offered them.
std::span<const GameInfo> allGames();

const char* toString(Game game);  ///< "8-ball", "9-ball", "10-ball"
/// 8, 9 or 10: the number that names the game (`--game 9`).
int gameNumber(Game game);
/// The game of number 8, 9 or 10; empty otherwise.
std::optional<Game> gameOfNumber(long number);
/// The rack the game is played from.
table::RackType rackTypeOf(Game game);

/// A game and its rule options.
struct GameRules {
  Game game = Game::EightBall;
  EightBallConfig eight_ball;  ///< calls and stalemate (the stalemate count serves every game)

  RotationConfig rotation() const;
};

/// checkIntent or checkRotationIntent, by game.
Check<> checkIntentFor(const GameRules& rules, const GameState& state, const Intent& intent,
                       const std::vector<physics::Ball>& balls);

/// judgeEightBall or judgeRotation, by game.
Result<Verdict> judgeShot(const GameRules& rules, const GameState& state, const Shot& shot,
                          const TableContext& table);

/// applyChoice or applyRotationChoice, by game.
Result<Verdict> applyChoiceFor(const GameRules& rules, const GameState& state, Choice choice,
                               const std::vector<physics::Ball>& balls, const TableContext& table);

/// legalFirstBalls or rotationFirstBalls, by game.
std::vector<int> firstBallsFor(const GameRules& rules, const GameState& state,
                               const std::vector<physics::Ball>& balls);

}  // namespace pool::rules
