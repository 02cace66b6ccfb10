// Frames and event logs of the match passed on to the sound board.
#include "client/ui/window_sound.h"

namespace pool::ui {
namespace {

audio::SoundOptions soundOptions(bool mute, double volume) {
  audio::SoundOptions o;
  o.mute = mute;
  o.mixer.master = static_cast<float>(volume);
  return o;
}

}  // namespace

SoundListener::SoundListener(bool mute, double volume) : board_(soundOptions(mute, volume)) {}

void SoundListener::onFrame(const client::TableFrame& frame) {
  board_.onFrame(frame.shot_number, frame.sim_time, frame.balls);
}

void SoundListener::onShot(const client::ShotReport& report) {
  board_.onShot(report.events, report.shot_number);
}

}  // namespace pool::ui
