// Shots of 9-ball and 10-ball after the break: the lowest ball first, push-outs, calls, the rack
// ball.
#include "rules/rotation_steps.h"

namespace pool::rules::detail {
namespace {

// Fouls about the first contact, excused on a push-out.
void contactFouls(const Shot& shot, const ShotFacts& facts, std::vector<Foul>& fouls) {
  if (facts.first_contact < 0) {
    fouls.push_back(Foul::NoBallHit);
    return;
  }
  if (facts.first_contact != lowestBall(shot.before)) fouls.push_back(Foul::WrongBallFirst);
  if (!facts.cushion_after_contact && facts.objectBallsPocketed().empty()) {
    fouls.push_back(Foul::NoCushionAfterContact);
  }
}

// The opponent decides who shoots the next shot from the table as it lies.
void offerPassBack(const GameState& state, Verdict& v) {
  passTurn(state, BallInHand::None, v);
  v.options = {Choice::PlayOn, Choice::PassBack};
}

// The called ball went into the called pocket.
bool callMade(const Intent& intent, const ShotFacts& facts) {
  return !intent.safety && intent.ball && facts.isPocketed(*intent.ball) &&
         facts.pocketOf(*intent.ball) == intent.pocket;
}

// A legal shot that is not a push-out.
void legalShot(const GameState& state, const Shot& shot, const ShotFacts& facts,
               const RotationConfig& config, Judged& judged) {
  Verdict& v = judged.verdict;
  const int rack_ball = rackBall(config.game);
  const bool rack_ball_down = facts.isPocketed(rack_ball);
  const Intent& intent = shot.intent;
  if (intent.safety) {
    if (rack_ball_down) judged.respot_ids.push_back(rack_ball);
    passTurn(state, BallInHand::None, v);
    return;
  }
  if (config.game == Rotation::NineBall) {
    if (rack_ball_down) {
      endGame(state, GameEnd::RackBallPocketed, v);
    } else if (!v.pocketed.empty()) {
      v.turn_continues = true;
      v.next_shooter = state.shooter;
    } else {
      passTurn(state, BallInHand::None, v);
    }
    return;
  }
  const bool made = callMade(intent, facts);
  if (made && *intent.ball == rack_ball) {
    endGame(state, GameEnd::RackBallPocketed, v);
    return;
  }
  if (rack_ball_down) judged.respot_ids.push_back(rack_ball);
  if (made) {
    v.turn_continues = true;
    v.next_shooter = state.shooter;
  } else if (!v.pocketed.empty()) {
    offerPassBack(state, v);
  } else {
    passTurn(state, BallInHand::None, v);
  }
}

}  // namespace

Judged judgeRotationPlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                         const RotationConfig& config) {
  Judged judged;
  Verdict& v = judged.verdict;
  v.fouls = leavingFouls(shot, facts);
  if (!state.push_out) contactFouls(shot, facts, v.fouls);
  v.pocketed = facts.objectBallsPocketed();
  v.off_table = facts.objectBallsOffTable();
  const int rack_ball = rackBall(config.game);
  if (facts.isOffTable(rack_ball)) judged.respot_ids.push_back(rack_ball);
  if (!v.fouls.empty()) {
    if (facts.isPocketed(rack_ball)) judged.respot_ids.push_back(rack_ball);
    rotationFoul(state, v);
    return judged;
  }
  if (state.push_out) {
    if (facts.isPocketed(rack_ball)) judged.respot_ids.push_back(rack_ball);
    offerPassBack(state, v);
    return judged;
  }
  legalShot(state, shot, facts, config, judged);
  return judged;
}

}  // namespace pool::rules::detail
