// The steps every rule set builds its verdicts from (verdict_steps.h).
#include "rules/verdict_steps.h"

#include "rules/placement.h"

namespace pool::rules::detail {

bool ballOnTable(int id, const std::vector<physics::Ball>& balls) {
  for (const auto& b : balls) {
    if (b.id == id) return physics::onTable(b.state);
  }
  return false;
}

void passTurn(const GameState& state, BallInHand in_hand, Verdict& verdict) {
  verdict.turn_continues = false;
  verdict.next_shooter = opponentOf(state.shooter);
  verdict.ball_in_hand = in_hand;
}

void endGame(const GameState& state, GameEnd end, Verdict& verdict) {
  verdict.game_over = true;
  verdict.end = end;
  const bool won = end == GameEnd::EightPocketed || end == GameEnd::RackBallPocketed;
  verdict.winner = won ? state.shooter : opponentOf(state.shooter);
  verdict.next_shooter = verdict.winner;
  verdict.ball_in_hand = BallInHand::None;
  verdict.options.clear();
}

GameState nextState(const GameState& state, const Verdict& verdict, int dry_turns) {
  if (verdict.rerack) return newRack(verdict.next_shooter);
  GameState next = state;
  if (verdict.game_over) {
    next.phase = Phase::Over;
    next.winner = verdict.winner;
    next.end = verdict.end;
    next.options.clear();
    next.ball_in_hand = BallInHand::None;
    return next;
  }
  if (next.phase == Phase::Break) next.phase = Phase::Open;
  if (verdict.assigned != Group::None) {
    next.groups[state.shooter] = verdict.assigned;
    next.groups[opponentOf(state.shooter)] = otherGroup(verdict.assigned);
    next.phase = Phase::Assigned;
  }
  next.shooter = verdict.next_shooter;
  next.ball_in_hand = verdict.ball_in_hand;
  next.options = verdict.options;
  next.dry_turns = dry_turns;
  next.push_out = false;
  return next;
}

Check<> checkCueInHand(const GameState& state, const Shot& shot, const TableContext& table) {
  if (state.ball_in_hand == BallInHand::None) return Check<>::pass();
  for (const auto& b : shot.before) {
    if (b.id != physics::kCueBall) continue;
    PlacementCheck check =
        checkCueBallPlacement(state.ball_in_hand, b.pos.head<2>(), shot.before, table);
    if (!check.ok())
      return Check<>::refuse(toString(check.code()), "cue ball in hand: " + check.error());
  }
  return Check<>::pass();
}

void addWatchdogRemovals(const ShotFacts& facts, Judged& judged) {
  for (int id : facts.removed) {
    if (id == physics::kCueBall && judged.verdict.ball_in_hand == BallInHand::None) {
      judged.verdict.ball_in_hand = BallInHand::Anywhere;
    } else if (id != physics::kCueBall) {
      judged.respot_ids.push_back(id);
    }
  }
}

std::vector<Foul> leavingFouls(const Shot& shot, const ShotFacts& facts) {
  std::vector<Foul> fouls;
  if (facts.isPocketed(physics::kCueBall)) fouls.push_back(Foul::CueBallPocketed);
  if (facts.isOffTable(physics::kCueBall)) fouls.push_back(Foul::CueBallOffTable);
  if (!facts.objectBallsOffTable().empty()) fouls.push_back(Foul::ObjectBallOffTable);
  if (shot.clock_expired) fouls.push_back(Foul::ShotClockExpired);
  return fouls;
}

void checkStalemate(const GameState& state, int dry_turns, int stalemate_turns, Verdict& v) {
  if (v.game_over || v.rerack || !v.options.empty()) return;
  if (stalemate_turns <= 0 || dry_turns < stalemate_turns) return;
  v.rerack = true;
  v.stalemate = true;
  v.turn_continues = false;
  v.next_shooter = state.breaker;
  v.ball_in_hand = BallInHand::BehindHeadString;
  v.respots.clear();
}

Judged timeOut(const GameState& state) {
  Judged judged;
  Verdict& v = judged.verdict;
  v.fouls.push_back(Foul::ShotClockExpired);
  bool breaking = state.phase == Phase::Break;
  passTurn(state, breaking ? BallInHand::BehindHeadString : BallInHand::Anywhere, v);
  // The rack still stands: "re-racking" it only hands the break over.
  v.rerack = breaking;
  return judged;
}

Verdict rerackVerdict(int breaker) {
  Verdict v;
  v.rerack = true;
  v.next_shooter = breaker;
  v.ball_in_hand = BallInHand::BehindHeadString;
  v.next = newRack(breaker);
  return v;
}

Verdict playOnVerdict(const GameState& state, BallInHand in_hand) {
  Verdict v;
  v.turn_continues = true;
  v.next_shooter = state.shooter;
  v.ball_in_hand = in_hand;
  v.next = state;
  v.next.options.clear();
  v.next.ball_in_hand = in_hand;
  return v;
}

}  // namespace pool::rules::detail
