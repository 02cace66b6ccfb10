// The opening break of 8-ball: legal or not, scratches, jumped balls and the 8 on the break.
#include "rules/eight_ball_steps.h"

namespace pool::rules::detail {
namespace {

// The 8 down on the break: re-spot it or break again. The breaker chooses, unless the break also
// fouled: then the incoming player chooses and, re-spotting, has the cue ball behind the head
// string.
void eightOnBreak(const GameState& state, bool fouled, Verdict& v) {
  v.options = {Choice::RespotEight, Choice::ReBreak};
  if (fouled) {
    passTurn(state, BallInHand::BehindHeadString, v);
    return;
  }
  v.turn_continues = true;
  v.next_shooter = state.shooter;
  v.ball_in_hand = BallInHand::None;
}

// Neither a ball down nor four object balls to a cushion: the incoming player plays on (in hand
// behind the head string after a scratch), or re-racks and breaks, or has the breaker break again.
void illegalBreak(const GameState& state, bool cue_lost, Verdict& v) {
  v.fouls.insert(v.fouls.begin(), Foul::IllegalBreak);
  passTurn(state, cue_lost ? BallInHand::BehindHeadString : BallInHand::None, v);
  v.options = {Choice::PlayOn, Choice::ReBreak, Choice::OpponentReBreaks};
}

// A legal break: a scratch gives ball in hand behind the head string; a jumped object ball lets the
// incoming player take that or play on; a clean break with a ball down keeps the breaker shooting.
void legalBreak(const GameState& state, bool cue_lost, Verdict& v) {
  if (cue_lost || v.hasFoul(Foul::ShotClockExpired)) {
    passTurn(state, BallInHand::BehindHeadString, v);
  } else if (v.hasFoul(Foul::ObjectBallOffTable)) {
    passTurn(state, BallInHand::None, v);
    v.options = {Choice::PlayOn, Choice::BallInHand};
  } else if (!v.pocketed.empty()) {
    v.turn_continues = true;
    v.next_shooter = state.shooter;
  } else {
    passTurn(state, BallInHand::None, v);
  }
}

}  // namespace

Judged judgeBreak(const GameState& state, const Shot& shot, const ShotFacts& facts) {
  Judged judged;
  Verdict& v = judged.verdict;
  v.fouls = leavingFouls(shot, facts);
  v.pocketed = facts.objectBallsPocketed();
  v.off_table = facts.objectBallsOffTable();
  bool cue_lost = facts.cueBallLost();
  // The 8 jumped off on the break is not a loss; it goes back on the foot spot.
  if (facts.isOffTable(kEightBall)) judged.respot_ids.push_back(kEightBall);
  bool legal = !v.pocketed.empty() || facts.cushioned.size() >= 4;
  if (facts.isPocketed(kEightBall)) {
    eightOnBreak(state, !v.fouls.empty(), v);
  } else if (!legal) {
    illegalBreak(state, cue_lost, v);
  } else {
    legalBreak(state, cue_lost, v);
  }
  return judged;
}

}  // namespace pool::rules::detail
