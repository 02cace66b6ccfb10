// Which game a match plays and the one entry to its rule set.
#include "rules/game_rules.h"

namespace pool::rules {

namespace {

// One row a game: adding a game starts here (docs/ARCHITECTURE.md, "Adding a game").
constexpr GameInfo kGames[] = {
    {Game::EightBall, "8-ball", 8, table::RackType::EightBall, nullptr},
    {Game::NineBall, "9-ball", 9, table::RackType::NineBall, nullptr},
    {Game::TenBall, "10-ball", 10, table::RackType::TenBall, nullptr},
    {Game::ThreeCushion, "three-cushion", 3, table::RackType::ThreeCushion, "carom-match"},
    {Game::Snooker, "snooker", 22, table::RackType::Snooker, "snooker-12ft"},
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

std::optional<Game> gameOfName(std::string_view name) {
  for (const GameInfo& g : kGames) {
    if (name == g.name || name == std::to_string(g.number)) return g.game;
  }
  return std::nullopt;
}

std::string tableOf(Game game, const std::string& pool_table) {
  const GameInfo* g = find(game);
  return g && g->table ? std::string(g->table) : pool_table;
}

bool isPool(Game game) {
  return game == Game::EightBall || game == Game::NineBall || game == Game::TenBall;
}

int cueBallFor(const GameRules& rules, const GameState& state) {
  return rules.game == Game::ThreeCushion ? caromBallOf(state, state.shooter) : physics::kCueBall;
}

table::RackType rackTypeOf(Game game) {
  const GameInfo* g = find(game);
  return g ? g->rack : table::RackType::EightBall;
}

GameState newRackOf(Game game, int breaker) {
  GameState state = newRack(breaker);
  if (game == Game::ThreeCushion) state.ball_in_hand = BallInHand::None;
  if (game == Game::Snooker) state = newFrame(breaker);
  return state;
}

SnookerConfig GameRules::snooker() const {
  SnookerConfig config;
  config.stalemate_turns = eight_ball.stalemate_turns;
  return config;
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
  if (rules.game == Game::ThreeCushion) return checkCaromIntent(intent);
  if (rules.game == Game::Snooker) return checkSnookerIntent(state, intent);
  return checkRotationIntent(state, intent, balls, rules.rotation());
}

Result<Verdict> judgeShot(const GameRules& rules, const GameState& state, const Shot& shot,
                          const TableContext& table) {
  if (rules.game == Game::EightBall) return judgeEightBall(state, shot, table, rules.eight_ball);
  if (rules.game == Game::ThreeCushion)
    return judgeThreeCushion(state, shot, table, rules.three_cushion);
  if (rules.game == Game::Snooker) return judgeSnooker(state, shot, table, rules.snooker());
  return judgeRotation(state, shot, table, rules.rotation());
}

Result<Verdict> applyChoiceFor(const GameRules& rules, const GameState& state, Choice choice,
                               const std::vector<physics::Ball>& balls, const TableContext& table) {
  if (rules.game == Game::EightBall) return applyChoice(state, choice, balls, table);
  if (rules.game == Game::ThreeCushion)
    return Result<Verdict>::fail("three-cushion offers no choice");
  if (rules.game == Game::Snooker) return applySnookerChoice(state, choice);
  return applyRotationChoice(state, choice);
}

std::vector<int> firstBallsFor(const GameRules& rules, const GameState& state,
                               const std::vector<physics::Ball>& balls) {
  if (rules.game == Game::EightBall) return legalFirstBalls(state, balls);
  if (rules.game == Game::ThreeCushion) {
    if (state.phase == Phase::Break) return {kCaromRed};
    const int own = caromBallOf(state, state.shooter);
    return {own == kCaromWhite ? kCaromYellow : kCaromWhite, kCaromRed};
  }
  if (rules.game == Game::Snooker) {
    if (!state.free_ball) return snookerBallsOn(state, balls);
    std::vector<int> all;
    for (const auto& b : balls) {
      if (b.id != physics::kCueBall && physics::onTable(b.state)) all.push_back(b.id);
    }
    return all;
  }
  return rotationFirstBalls(balls);
}

}  // namespace pool::rules
