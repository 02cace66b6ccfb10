// The window's sound: the match's frames and shot logs into a sound board.
#pragma once

#include "client/app/match_session.h"
#include "client/audio/sound_board.h"

namespace pool::ui {

/// Hears the match followed and plays it on a SoundBoard (silent when `mute`).
class SoundListener final : public app::ShotListener {
 public:
  /// `volume`: the master gain, 0–1.
  SoundListener(bool mute, double volume);
  void onFrame(const client::TableFrame& frame) override;
  void onShot(const client::ShotReport& report) override;
  /// Plays what is due at `playback_time` (s since the strike of the shot being drawn).
  void update(double playback_time) { board_.update(playback_time); }

 private:
  audio::SoundBoard board_;
};

}  // namespace pool::ui
