// The WPA 8-ball referee: from a checked shot to a verdict and the next state.
#include "rules/eight_ball.h"

#include "rules/eight_ball_detail.h"
#include "rules/placement.h"
#include "rules/respot.h"
#include "rules/shot_facts.h"

namespace pool::rules {
namespace detail {

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

Result<bool> checkCueInHand(const GameState& state, const Shot& shot, const TableContext& table) {
  if (state.ball_in_hand == BallInHand::None) return Result<bool>::ok(true);
  for (const auto& b : shot.before) {
    if (b.id != physics::kCueBall) continue;
    PlacementCheck check =
        checkCueBallPlacement(state.ball_in_hand, b.pos.head<2>(), shot.before, table);
    if (!check.ok()) return Result<bool>::fail("cue ball in hand: " + check.reason());
  }
  return Result<bool>::ok(true);
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

}  // namespace detail

namespace {

using detail::Judged;

// A choice answered with the shot (play on, or ball in hand) applies before it.
GameState stateForShot(const GameState& state, const Intent& intent) {
  GameState st = state;
  if (!intent.choice) return st;
  if (*intent.choice == Choice::BallInHand) st.ball_in_hand = BallInHand::BehindHeadString;
  st.options.clear();
  return st;
}

Verdict finish(const GameState& state, const Shot& shot, Judged judged, const TableContext& table,
               const EightBallConfig& config) {
  Verdict& v = judged.verdict;
  if (!v.game_over) v.respots = respotBalls(judged.respot_ids, shot.after, table);
  int dry_turns = v.pocketed.empty() ? state.dry_turns + 1 : 0;
  detail::checkStalemate(state, dry_turns, config.stalemate_turns, v);
  v.next = detail::nextState(state, v, dry_turns);
  return v;
}

}  // namespace

Result<Verdict> judgeEightBall(const GameState& state, const Shot& shot, const TableContext& table,
                               const EightBallConfig& config) {
  if (auto ok = checkIntent(state, shot.intent, shot.before, config); !ok)
    return Result<Verdict>::fail(ok.error());
  GameState st = stateForShot(state, shot.intent);
  if (auto ok = detail::checkCueInHand(st, shot, table); !ok)
    return Result<Verdict>::fail(ok.error());
  if (shot.clock_expired && shot.events.empty())
    return Result<Verdict>::ok(finish(st, shot, detail::timeOut(st), table, config));
  auto facts = distilShot(shot, table.spots.head_string_x);
  if (!facts) return Result<Verdict>::fail(facts.error());
  Judged judged = st.phase == Phase::Break ? detail::judgeBreak(st, shot, *facts)
                                           : detail::judgePlay(st, shot, *facts, table, config);
  detail::addWatchdogRemovals(*facts, judged);
  return Result<Verdict>::ok(finish(st, shot, std::move(judged), table, config));
}

}  // namespace pool::rules
