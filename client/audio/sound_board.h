// The client's sound: one object told each shot's events and each frame's playback time.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "client/audio/audio_sink.h"
#include "client/audio/cue_schedule.h"
#include "client/audio/frame_impacts.h"
#include "client/audio/impact_law.h"
#include "client/audio/mixer.h"
#include "client/audio/sound_bank.h"
#include "physics/events.h"

namespace pool::audio {

struct SoundOptions {
  bool mute = false;  ///< play nothing (the silent sink still keeps time)
  int rate = kDefaultSampleRate;
  ImpactLaws laws;
  MixerOptions mixer;  ///< its rate is set from `rate`
  ScheduleOptions schedule;
  SinkOptions sink;  ///< its rate and mute are set from the fields above
  /// Where the one line about the output goes (default: stderr).
  std::function<void(const std::string&)> log;
};

/// Sound from the server's events. Usage, from the app loop:
///   audio::SoundBoard board(options);
///   board.onShot(report.events, report.shot_number);  // when a shot's event log arrives
///   board.onFrame(frame.shot_number, frame.sim_time, frame.balls);  // each TableFrame received
///   board.update(playback_time);                      // every rendered frame
/// update() starts the sounds whose event time playback has reached (each once; none lost when
/// frames are skipped; a shot joined late skips what happened before), then tops up the output.
/// The server sends a shot's event log after its last frame: until then the impacts read off
/// the frames sound, and the log of a shot that already sounded is not played again.
/// With no audio device it plays silently; it never blocks.
class SoundBoard {
 public:
  /// Settings out of range (rate outside [8000, 192000] Hz, voices outside [1, 256], ...) fall
  /// back to their defaults with one log line each.
  explicit SoundBoard(const SoundOptions& options = {});
  /// With a given output (tests, tools); null: the device or silence, as above.
  SoundBoard(const SoundOptions& options, std::unique_ptr<AudioSink> sink);

  /// A shot's event log. Replaces the previous shot's cues still to come (sounds already playing
  /// ring out). `shot_key` ≠ 0 identifies the shot (its number, which grows): the same key again,
  /// an older one, or that of a shot already sounding from its frames is ignored, and the log
  /// sounds only once a frame of its shot arrives (a report of a shot already over, as a late
  /// joiner receives, stays silent). With key 0 it sounds from the next update.
  void onShot(const physics::EventLog& events, std::uint64_t shot_key = 0);

  /// One table frame of shot `shot_key`. Unless that shot's event log is known, the impacts
  /// read off consecutive frames (FrameImpacts) are added to the shot's sounds.
  void onFrame(std::uint64_t shot_key, double sim_time, const std::vector<physics::Ball>& balls);

  /// The current playback time of the shot, s since the strike.
  void update(double playback_time);

  bool silent() const { return sink_->silent(); }
  std::string outputName() const { return sink_->name(); }
  const MixerStats& mixerStats() const { return mixer_.stats(); }
  const CueSchedule& schedule() const { return schedule_; }
  const SoundBank& bank() const { return bank_; }

 private:
  void pump();
  /// True for a shot older than the newest seen (then nothing of it sounds); notes new ones.
  bool stale(std::uint64_t shot_key);

  SoundOptions options_;
  SoundBank bank_;
  Mixer mixer_;
  CueSchedule schedule_;
  FrameImpacts impacts_;
  std::optional<std::uint64_t> frames_key_;  ///< the shot sounding from its frames
  std::optional<std::uint64_t> events_key_;  ///< the shot sounding from its event log
  std::optional<std::uint64_t> latest_key_;  ///< the newest shot seen: older ones are stale
  bool armed_ = true;  ///< the current shot's cues may start (a numbered log waits for a frame)
  std::unique_ptr<AudioSink> sink_;
  std::vector<DueCue> due_;   ///< reused each update
  std::vector<float> block_;  ///< one block of mixed samples
};

}  // namespace pool::audio
