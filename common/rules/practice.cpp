// The practice rule set: one player, no fouls, re-rack and re-place balls on demand.
#include "rules/practice.h"

#include "rules/placement.h"
#include "rules/respot.h"
#include "rules/shot_facts.h"

namespace pool::rules {
namespace {

// Replaces ball `moved.id` in `balls`, or adds it.
void putBall(std::vector<physics::Ball>& balls, const physics::Ball& moved) {
  for (auto& b : balls) {
    if (b.id == moved.id) {
      b = moved;
      return;
    }
  }
  balls.push_back(moved);
}

}  // namespace

int practiceMaxBallId(Game game) {
  switch (game) {
    case Game::Snooker:
      return table::kSnookerBlack;
    case Game::ThreeCushion:
      return kCaromRed;
    case Game::EightBall:
    case Game::NineBall:
    case Game::TenBall:
      break;
  }
  return 15;  // a pool set: the cue ball and 15 object balls
}

GameState practiceState() {
  GameState state;
  state.phase = Phase::Open;
  state.ball_in_hand = BallInHand::Anywhere;
  return state;
}

Result<Verdict> judgePractice(const Shot& shot, const TableContext& table) {
  auto facts = distilShot(shot, table.spots.head_string_x);
  if (!facts) return Result<Verdict>::fail(facts.error());
  Verdict v;
  v.pocketed = facts->objectBallsPocketed();
  v.off_table = facts->objectBallsOffTable();
  v.turn_continues = true;
  bool cue_lost = facts->cueBallLost() || facts->isRemoved(physics::kCueBall);
  v.ball_in_hand = cue_lost ? BallInHand::Anywhere : BallInHand::None;
  std::vector<int> back;
  for (int id : facts->removed) {
    if (id != physics::kCueBall) back.push_back(id);
  }
  v.respots = respotBalls(back, shot.after, table);
  v.next = practiceState();
  v.next.ball_in_hand = v.ball_in_hand;
  return Result<Verdict>::ok(v);
}

std::vector<physics::Ball> practiceRack(const TableContext& table, std::uint64_t seed) {
  std::vector<physics::Ball> balls;
  balls.push_back(
      physics::restingBall(physics::kCueBall, table.spots.head_spot, table.ball_radius));
  for (const auto& p :
       table::rackBalls(table::RackType::EightBall, table.spec, table.ball_radius, seed)) {
    balls.push_back(physics::restingBall(p.id, p.pos, table.ball_radius));
  }
  return balls;
}

Result<std::vector<physics::Ball>> placeBalls(const std::vector<physics::Ball>& balls,
                                              const std::vector<table::BallPlacement>& moves,
                                              const TableContext& table, Game game) {
  const int max_id = practiceMaxBallId(game);
  std::vector<physics::Ball> placed = balls;
  for (const auto& move : moves) {
    std::string name = "ball " + std::to_string(move.id);
    if (move.id < 0 || move.id > max_id) {
      return Result<std::vector<physics::Ball>>::fail(name + ": not a ball id (0-" +
                                                      std::to_string(max_id) + ")");
    }
    PlacementCheck check = checkBallPlacement(move.id, move.pos, placed, table);
    if (!check.ok()) return Result<std::vector<physics::Ball>>::fail(name + ": " + check.error());
    putBall(placed, physics::restingBall(move.id, move.pos, table.ball_radius));
  }
  return Result<std::vector<physics::Ball>>::ok(std::move(placed));
}

}  // namespace pool::rules
