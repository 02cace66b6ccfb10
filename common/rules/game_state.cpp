// The state of one rack between shots, and names of its enums.
#include "rules/game_state.h"

namespace pool::rules {

const char* toString(Phase phase) {
  switch (phase) {
    case Phase::Break:
      return "break";
    case Phase::Open:
      return "open";
    case Phase::Assigned:
      return "assigned";
    case Phase::Over:
      return "over";
  }
  return "unknown";
}

const char* toString(BallInHand ball_in_hand) {
  switch (ball_in_hand) {
    case BallInHand::None:
      return "none";
    case BallInHand::Anywhere:
      return "anywhere";
    case BallInHand::BehindHeadString:
      return "behind_head_string";
    case BallInHand::InTheD:
      return "in_the_d";
  }
  return "unknown";
}

const char* toString(Choice choice) {
  switch (choice) {
    case Choice::PlayOn:
      return "play_on";
    case Choice::BallInHand:
      return "ball_in_hand";
    case Choice::RespotEight:
      return "respot_eight";
    case Choice::ReBreak:
      return "re_break";
    case Choice::OpponentReBreaks:
      return "opponent_re_breaks";
    case Choice::PushOut:
      return "push_out";
    case Choice::PassBack:
      return "pass_back";
    case Choice::FreeBall:
      return "free_ball";
    case Choice::Replace:
      return "replace";
  }
  return "unknown";
}

const char* toString(GameEnd end) {
  switch (end) {
    case GameEnd::None:
      return "none";
    case GameEnd::EightPocketed:
      return "eight_pocketed";
    case GameEnd::EightOnFoul:
      return "eight_on_foul";
    case GameEnd::EightBeforeGroupCleared:
      return "eight_before_group_cleared";
    case GameEnd::EightWithLastGroupBall:
      return "eight_with_last_group_ball";
    case GameEnd::EightWrongPocket:
      return "eight_wrong_pocket";
    case GameEnd::EightOffTable:
      return "eight_off_table";
    case GameEnd::Forfeit:
      return "forfeit";
    case GameEnd::RackBallPocketed:
      return "rack_ball_pocketed";
    case GameEnd::ThreeFouls:
      return "three_fouls";
    case GameEnd::PointsReached:
      return "points_reached";
    case GameEnd::FrameOver:
      return "frame_over";
    case GameEnd::ThreeMisses:
      return "three_misses";
  }
  return "unknown";
}

GameState newRack(int breaker) {
  GameState state;
  state.shooter = breaker;
  state.breaker = breaker;
  return state;
}

std::string describe(const GameState& state) {
  std::string text = toString(state.phase);
  if (state.phase == Phase::Over) {
    return text + ", seat " + std::to_string(state.winner) + " won (" + toString(state.end) + ")";
  }
  text += ", seat " + std::to_string(state.shooter) + " to shoot";
  if (state.groups[state.shooter] != Group::None) {
    text += std::string(" (") + toString(state.groups[state.shooter]) + ")";
  }
  if (state.ball_in_hand != BallInHand::None) {
    text += std::string(", ball in hand ") + toString(state.ball_in_hand);
  }
  for (std::size_t i = 0; i < state.options.size(); ++i) {
    text += (i == 0 ? ", choose " : " or ");
    text += toString(state.options[i]);
  }
  if (state.push_out) text += ", push-out";
  if (state.free_ball) text += ", free ball";
  if (state.points[0] > 0 || state.points[1] > 0) {
    text += ", points " + std::to_string(state.points[0]) + "-" + std::to_string(state.points[1]);
  }
  if (int fouls = state.fouls_in_row[state.shooter]; fouls > 0) {
    text += ", " + std::to_string(fouls) + (fouls == 1 ? " foul" : " fouls") + " in a row";
  }
  return text;
}

}  // namespace pool::rules
