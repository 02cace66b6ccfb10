// Frames and event logs of the match passed on to the sound board.
#include "client/ui/window_sound.h"

namespace pool::ui {
namespace {

audio::SoundOptions soundOptions(bool mute) {
  audio::SoundOptions o;
  o.mute = mute;
  return o;
}

}  // namespace

SoundListener::SoundListener(bool mute) : board_(soundOptions(mute)) {}

void SoundListener::onFrame(const client::TableFrame& frame) {
  board_.onFrame(frame.shot_number, frame.sim_time, frame.balls);
}

void SoundListener::onShot(const client::ShotReport& report) {
  board_.onShot(report.events, report.shot_number);
}

}  // namespace pool::ui
