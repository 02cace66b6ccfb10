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
  }
  return "unknown";
}

bool optionShoots(ShotOption option) {
  return option != ShotOption::ReBreak && option != ShotOption::OpponentReBreaks &&
         option != ShotOption::PassBack;
}

}  // namespace pool::protocol
