// Which game a match plays and the one entry to its rule set.
#include "rules/game_rules.h"

namespace pool::rules {

const char* toString(Game game) {
  switch (game) {
    case Game::EightBall:
      return "8-ball";
    case Game::NineBall:
      return "9-ball";
    case Game::TenBall:
      return "10-ball";
  }
  return "unknown";
}

int gameNumber(Game game) {
  switch (game) {
    case Game::EightBall:
      return 8;
    case Game::NineBall:
      return 9;
    case Game::TenBall:
      return 10;
  }
  return 0;
}

std::optional<Game> gameOfNumber(long number) {
  if (number == 8) return Game::EightBall;
  if (number == 9) return Game::NineBall;
  if (number == 10) return Game::TenBall;
  return std::nullopt;
}

table::RackType rackTypeOf(Game game) {
  switch (game) {
    case Game::EightBall:
      return table::RackType::EightBall;
    case Game::NineBall:
      return table::RackType::NineBall;
    case Game::TenBall:
      return table::RackType::TenBall;
  }
  return table::RackType::EightBall;
}

RotationConfig GameRules::rotation() const {
  RotationConfig config;
  config.game = game == Game::TenBall ? Rotation::TenBall : Rotation::NineBall;
  config.stalemate_turns = eight_ball.stalemate_turns;
  return config;
}

Result<bool> checkIntentFor(const GameRules& rules, const GameState& state, const Intent& intent,
                            const std::vector<physics::Ball>& balls) {
  if (rules.game == Game::EightBall) return checkIntent(state, intent, balls, rules.eight_ball);
  return checkRotationIntent(state, intent, balls, rules.rotation());
}

Result<Verdict> judgeShot(const GameRules& rules, const GameState& state, const Shot& shot,
                          const TableContext& table) {
  if (rules.game == Game::EightBall) return judgeEightBall(state, shot, table, rules.eight_ball);
  return judgeRotation(state, shot, table, rules.rotation());
}

Result<Verdict> applyChoiceFor(const GameRules& rules, const GameState& state, Choice choice,
                               const std::vector<physics::Ball>& balls, const TableContext& table) {
  if (rules.game == Game::EightBall) return applyChoice(state, choice, balls, table);
  return applyRotationChoice(state, choice);
}

std::vector<int> firstBallsFor(const GameRules& rules, const GameState& state,
                               const std::vector<physics::Ball>& balls) {
  if (rules.game == Game::EightBall) return legalFirstBalls(state, balls);
  return rotationFirstBalls(balls);
}

}  // namespace pool::rules
