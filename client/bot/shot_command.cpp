// Planned shots to shot requests.
#include "client/bot/shot_command.h"

namespace pool::bot {

protocol::ShotRequest requestOf(const PlannedShot& shot) {
  protocol::ShotRequest request;
  request.cue = shot.cue;
  if (!shoots(shot)) {
    request.cue = physics::CueShot{};
    request.cue.speed = 1.0;
    request.cue.speed_is_ball = true;
  }
  const rules::Intent intent = intentOf(shot);
  request.called_ball = intent.ball;
  request.called_pocket = intent.pocket;
  request.safety = intent.safety;
  request.cue_ball_at = shot.cue_ball_at;
  request.option = shot.choice ? protocol::optionOf(*shot.choice) : protocol::ShotOption::None;
  return request;
}

}  // namespace pool::bot
