// The judging pipeline every rule set runs (referee.h).
#include "rules/referee.h"

#include <array>
#include <optional>

#include "rules/respot.h"

namespace pool::rules::detail {
namespace {

// The third foul in a row loses the rack; a legal shot clears the shooter's count. Returns the
// counts the next state carries.
std::array<int, kSeats> countFouls(const GameState& state, Verdict& v) {
  std::array<int, kSeats> fouls_in_row = state.fouls_in_row;
  int& mine = fouls_in_row[state.shooter];
  mine = v.legal() ? 0 : mine + 1;
  if (mine >= 3 && !v.game_over) endGame(state, GameEnd::ThreeFouls, v);
  return fouls_in_row;
}

Verdict finish(const Referee& referee, const GameState& state, const Shot& shot, Judged judged,
               const TableContext& table) {
  Verdict& v = judged.verdict;
  std::optional<std::array<int, kSeats>> fouls_in_row;
  if (referee.threeFoulsLose()) fouls_in_row = countFouls(state, v);
  if (!v.game_over) v.respots = respotBalls(judged.respot_ids, shot.after, table);
  const int dry_turns = v.pocketed.empty() ? state.dry_turns + 1 : 0;
  checkStalemate(state, dry_turns, referee.stalemateTurns(), v);
  v.next = nextState(state, v, dry_turns);
  if (fouls_in_row && !v.rerack) v.next.fouls_in_row = *fouls_in_row;
  return v;
}

Judged judgeStrike(const Referee& referee, const GameState& state, const Shot& shot,
                   const ShotFacts& facts, const TableContext& table) {
  Judged judged = state.phase == Phase::Break ? referee.judgeBreak(state, shot, facts, table)
                                              : referee.judgePlay(state, shot, facts, table);
  addWatchdogRemovals(facts, judged);
  return judged;
}

}  // namespace

Result<Verdict> judgeWith(const Referee& referee, const GameState& state, const Shot& shot,
                          const TableContext& table) {
  if (auto ok = referee.checkIntent(state, shot.intent, shot.before); !ok)
    return Result<Verdict>::fail(ok.error());
  const GameState st = referee.stateForShot(state, shot.intent);
  if (auto ok = checkCueInHand(st, shot, table); !ok) return Result<Verdict>::fail(ok.error());
  if (shot.clock_expired && shot.events.empty())
    return Result<Verdict>::ok(finish(referee, st, shot, timeOut(st), table));
  auto facts = distilShot(shot, table.spots.head_string_x);
  if (!facts) return Result<Verdict>::fail(facts.error());
  return Result<Verdict>::ok(
      finish(referee, st, shot, judgeStrike(referee, st, shot, *facts, table), table));
}

}  // namespace pool::rules::detail
