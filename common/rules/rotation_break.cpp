// The opening break of 9-ball and 10-ball: legal or not, the lowest ball first, the rack ball on
// the break.
#include "rules/rotation_steps.h"

namespace pool::rules::detail {

void rotationFoul(const GameState& state, Verdict& verdict) {
  passTurn(state, BallInHand::Anywhere, verdict);
  verdict.options.clear();
}

Judged judgeRotationBreak(const GameState& state, const Shot& shot, const ShotFacts& facts,
                          const RotationConfig& config) {
  Judged judged;
  Verdict& v = judged.verdict;
  v.fouls = leavingFouls(shot, facts);
  v.pocketed = facts.objectBallsPocketed();
  v.off_table = facts.objectBallsOffTable();
  const int lowest = lowestBall(shot.before);
  if (facts.first_contact < 0) {
    v.fouls.push_back(Foul::NoBallHit);
  } else if (facts.first_contact != lowest) {
    v.fouls.push_back(Foul::WrongBallFirst);
  }
  const bool open = !v.pocketed.empty() || facts.cushioned.size() >= 4;
  if (!open) v.fouls.insert(v.fouls.begin(), Foul::IllegalBreak);

  const int rack_ball = rackBall(config.game);
  const bool rack_ball_down = facts.isPocketed(rack_ball);
  if (facts.isOffTable(rack_ball)) judged.respot_ids.push_back(rack_ball);
  // The 9 on a legal break wins; on a foul, and the 10 always, it comes back to the foot spot.
  if (rack_ball_down && v.fouls.empty() && config.game == Rotation::NineBall) {
    endGame(state, GameEnd::RackBallPocketed, v);
    return judged;
  }
  if (rack_ball_down) judged.respot_ids.push_back(rack_ball);

  if (!v.fouls.empty()) {
    rotationFoul(state, v);
    // 10-ball: after an illegal break (only that: a scratch on an open break is a plain foul)
    // the incoming player may also have the rack broken again.
    const bool only_illegal = v.fouls.size() == 1 && v.hasFoul(Foul::IllegalBreak);
    if (config.game == Rotation::TenBall && only_illegal) {
      v.options = {Choice::PlayOn, Choice::ReBreak, Choice::OpponentReBreaks};
    } else {
      v.options = {Choice::PlayOn, Choice::PushOut};
    }
    return judged;
  }
  // A legal break: a ball down keeps the breaker at the table; either way the next shot may be
  // a push-out.
  if (!v.pocketed.empty()) {
    v.turn_continues = true;
    v.next_shooter = state.shooter;
    v.ball_in_hand = BallInHand::None;
  } else {
    passTurn(state, BallInHand::None, v);
  }
  v.options = {Choice::PlayOn, Choice::PushOut};
  return judged;
}

}  // namespace pool::rules::detail
