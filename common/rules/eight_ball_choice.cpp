// Choices the 8-ball rules offer (play on, ball in hand, re-spot the 8, re-break), stalemates and
// forfeits.
#include <algorithm>

#include "rules/respot.h"
#include "rules/verdict_steps.h"

namespace pool::rules {

using detail::playOnVerdict;
using detail::rerackVerdict;

Result<Verdict> applyChoice(const GameState& state, Choice choice,
                            const std::vector<physics::Ball>& balls, const TableContext& table) {
  const auto& options = state.options;
  if (std::find(options.begin(), options.end(), choice) == options.end()) {
    return Result<Verdict>::fail(std::string("choice ") + toString(choice) + " is not offered");
  }
  switch (choice) {
    case Choice::PlayOn:
      return Result<Verdict>::ok(playOnVerdict(state, state.ball_in_hand));
    case Choice::BallInHand:
      return Result<Verdict>::ok(playOnVerdict(state, BallInHand::BehindHeadString));
    case Choice::ReBreak:
      return Result<Verdict>::ok(rerackVerdict(state.shooter));
    case Choice::OpponentReBreaks:
      return Result<Verdict>::ok(rerackVerdict(opponentOf(state.shooter)));
    case Choice::RespotEight:
      break;
    case Choice::PushOut:
    case Choice::PassBack:
    case Choice::FreeBall:
    case Choice::Replace:
      return Result<Verdict>::fail(std::string("choice ") + toString(choice) +
                                   " is not part of 8-ball");
  }
  if (detail::ballOnTable(kEightBall, balls))
    return Result<Verdict>::fail("the 8 is already on the table");
  Verdict v = playOnVerdict(state, state.ball_in_hand);
  v.respots = respotBalls({kEightBall}, balls, table);
  return Result<Verdict>::ok(v);
}

Result<Verdict> agreeStalemate(const GameState& state) {
  if (state.phase == Phase::Over) return Result<Verdict>::fail("the game is over");
  Verdict v = rerackVerdict(state.breaker);
  v.stalemate = true;
  return Result<Verdict>::ok(v);
}

Verdict forfeit(const GameState& state, int loser) {
  Verdict v;
  GameState st = state;
  st.shooter = loser;
  detail::endGame(st, GameEnd::Forfeit, v);
  v.next = detail::nextState(state, v, state.dry_turns);
  return v;
}

}  // namespace pool::rules
