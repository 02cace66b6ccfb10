// The send decision of the live aim: rate cap while it changes, keep-alive while it rests.
#include "client/net/aim_pacer.h"

namespace pool::client {
namespace {

bool sameCue(const protocol::AimSample& a, const protocol::AimSample& b) {
  return a.yaw == b.yaw && a.tip_side == b.tip_side && a.tip_height == b.tip_height &&
         a.elevation == b.elevation && a.power == b.power && a.stroke == b.stroke &&
         a.cue_ball_x == b.cue_ball_x && a.cue_ball_y == b.cue_ball_y;
}

}  // namespace

bool AimPacer::due(const protocol::AimSample& aim, double now) {
  bool send = false;
  if (!last_ || last_->shot_number != aim.shot_number || (aim.stroke && !last_->stroke)) {
    send = true;
  } else if (sameCue(aim, *last_)) {
    send = now - sent_at_ >= pace_.keep_alive;
  } else {
    send = now - sent_at_ >= 1.0 / pace_.max_rate;
  }
  if (send) {
    last_ = aim;
    sent_at_ = now;
  }
  return send;
}

}  // namespace pool::client
