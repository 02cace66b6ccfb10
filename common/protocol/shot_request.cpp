// Names and kinds of shot options.
#include "protocol/shot_request.h"

namespace pool::protocol {

const char* toString(ShotOption option) {
  switch (option) {
    case ShotOption::None:
      return "none";
    case ShotOption::PlayOn:
      return "play_on";
    case ShotOption::BallInHand:
      return "ball_in_hand";
    case ShotOption::RespotEight:
      return "respot_eight";
    case ShotOption::ReBreak:
      return "rebreak";
    case ShotOption::OpponentReBreaks:
      return "opponent_rebreaks";
    case ShotOption::PushOut:
      return "push_out";
    case ShotOption::PassBack:
      return "pass_back";
    case ShotOption::FreeBall:
      return "free_ball";
    case ShotOption::Replace:
      return "replace";
  }
  return "unknown";
}

bool optionShoots(ShotOption option) {
  return option != ShotOption::ReBreak && option != ShotOption::OpponentReBreaks &&
         option != ShotOption::PassBack && option != ShotOption::Replace;
}

ShotOption optionOf(rules::Choice choice) {
  switch (choice) {
    case rules::Choice::PlayOn:
      return ShotOption::PlayOn;
    case rules::Choice::BallInHand:
      return ShotOption::BallInHand;
    case rules::Choice::RespotEight:
      return ShotOption::RespotEight;
    case rules::Choice::ReBreak:
      return ShotOption::ReBreak;
    case rules::Choice::OpponentReBreaks:
      return ShotOption::OpponentReBreaks;
    case rules::Choice::PushOut:
      return ShotOption::PushOut;
    case rules::Choice::PassBack:
      return ShotOption::PassBack;
    case rules::Choice::FreeBall:
      return ShotOption::FreeBall;
    case rules::Choice::Replace:
      return ShotOption::Replace;
  }
  return ShotOption::None;
}

std::optional<rules::Choice> choiceOf(ShotOption option) {
  switch (option) {
    case ShotOption::None:
      return std::nullopt;
    case ShotOption::PlayOn:
      return rules::Choice::PlayOn;
    case ShotOption::BallInHand:
      return rules::Choice::BallInHand;
    case ShotOption::RespotEight:
      return rules::Choice::RespotEight;
    case ShotOption::ReBreak:
      return rules::Choice::ReBreak;
    case ShotOption::OpponentReBreaks:
      return rules::Choice::OpponentReBreaks;
    case ShotOption::PushOut:
      return rules::Choice::PushOut;
    case ShotOption::PassBack:
      return rules::Choice::PassBack;
    case ShotOption::FreeBall:
      return rules::Choice::FreeBall;
    case ShotOption::Replace:
      return rules::Choice::Replace;
  }
  return std::nullopt;
}

}  // namespace pool::protocol
