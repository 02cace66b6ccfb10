// Which game a match plays and the one entry to its rule set.
#include "rules/game_rules.h"

namespace pool::rules {

namespace {

// One row a game: adding a game starts here (docs/ARCHITECTURE.md, "Adding a game").
constexpr GameInfo kGames[] = {
    {Game::EightBall, "8-ball", 8, table::RackType::EightBall},
    {Game::NineBall, "9-ball", 9, table::RackType::NineBall},
    {Game::TenBall, "10-ball", 10, table::RackType::TenBall},
};

const GameInfo* find(Game game) {
  for (const GameInfo& g : kGames) {
    if (g.game == game) return &g;
  }
  return nullptr;
}

}  // namespace

std::span<const GameInfo> allGames() {
  return kGames;
}

const char* toString(Game game) {
  const GameInfo* g = find(game);
  return g ? g->name : "unknown";
}

int gameNumber(Game game) {
  const GameInfo* g = find(game);
  return g ? g->number : 0;
}

std::optional<Game> gameOfNumber(long number) {
  for (const GameInfo& g : kGames) {
    if (g.number == number) return g.game;
  }
  return std::nullopt;
}

table::RackType rackTypeOf(Game game) {
  const GameInfo* g = find(game);
  return g ? g->rack : table::RackType::EightBall;
}

RotationConfig GameRules::rotation() const {
  RotationConfig config;
  config.game = game == Game::TenBall ? Rotation::TenBall : Rotation::NineBall;
  config.stalemate_turns = eight_ball.stalemate_turns;
  return config;
}

Check<> checkIntentFor(const GameRules& rules, const GameState& state, const Intent& intent,
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
