// The sound board: events → cues → voices → the output, one update per frame.
#include "client/audio/sound_board.h"

#include <cmath>
#include <iostream>

namespace pool::audio {
namespace {

MixerOptions mixerOptionsOf(const SoundOptions& o) {
  MixerOptions m = o.mixer;
  m.rate = o.rate;
  return m;
}

SinkOptions sinkOptionsOf(const SoundOptions& o) {
  SinkOptions s = o.sink;
  s.rate = o.rate;
  s.mute = o.mute || s.mute;
  return s;
}

std::function<void(const std::string&)> logOf(const SoundOptions& o) {
  if (o.log) return o.log;
  return [](const std::string& line) { std::cerr << line << '\n'; };
}

/// Puts a setting outside [lo, hi] back to its default, saying so in one line.
template <class T>
void keepIn(T& value, T lo, T hi, T fallback, const char* what, const SoundOptions& o) {
  if (value >= lo && value <= hi) return;
  logOf(o)("sound: " + std::string(what) + " " + std::to_string(value) + " is outside [" +
           std::to_string(lo) + ", " + std::to_string(hi) + "]; using " + std::to_string(fallback));
  value = fallback;
}

SoundOptions checked(SoundOptions o) {
  keepIn(o.rate, 8000, 192000, kDefaultSampleRate, "sample rate (Hz)", o);
  keepIn(o.mixer.voices, 1, 256, MixerOptions{}.voices, "voices", o);
  keepIn(o.sink.block, std::size_t{64}, std::size_t{16384}, SinkOptions{}.block, "block (frames)",
         o);
  keepIn(o.sink.blocks, 2, 64, SinkOptions{}.blocks, "blocks queued", o);
  return o;
}

std::unique_ptr<AudioSink> openFor(const SoundOptions& o) {
  return openSink(sinkOptionsOf(o), logOf(o));
}

}  // namespace

SoundBoard::SoundBoard(const SoundOptions& options) : SoundBoard(options, nullptr) {}

SoundBoard::SoundBoard(const SoundOptions& options, std::unique_ptr<AudioSink> sink)
    : options_(checked(options)),
      bank_(options_.rate),
      mixer_(mixerOptionsOf(options_)),
      schedule_(options_.schedule),
      sink_(sink ? std::move(sink) : openFor(options_)) {
  block_.resize(sink_->blockFrames());
  due_.reserve(256);
}

bool SoundBoard::stale(std::uint64_t shot_key) {
  if (shot_key == 0) return false;
  if (latest_key_ && shot_key < *latest_key_) return true;
  latest_key_ = shot_key;
  return false;
}

void SoundBoard::onShot(const physics::EventLog& events, std::uint64_t shot_key) {
  // A shot that sounded from its frames is over when its log arrives: nothing to replay.
  if (stale(shot_key) || (shot_key != 0 && frames_key_ == shot_key)) return;
  if (shot_key != 0 && events_key_ == shot_key) return;  // the same report again
  events_key_ = shot_key;
  frames_key_.reset();
  schedule_.setShot(cuesFromEvents(events, options_.laws), shot_key);
  // A numbered log waits for a frame of its shot: the last shot's report, kept for late
  // joiners, belongs to a shot that is over and must not sound.
  armed_ = shot_key == 0;
}

void SoundBoard::onFrame(std::uint64_t shot_key, double sim_time,
                         const std::vector<physics::Ball>& balls) {
  if (stale(shot_key)) return;
  if (shot_key != 0 && events_key_ == shot_key) {
    armed_ = true;  // the exact log drives this shot, from its first frame on
    return;
  }
  armed_ = true;
  if (frames_key_ != shot_key) {
    frames_key_ = shot_key;
    events_key_.reset();
    impacts_.reset();
    schedule_.setShot({}, shot_key);
  }
  const auto events = impacts_.onFrame(balls, sim_time);
  if (!events.empty()) schedule_.addCues(cuesFromEvents(events, options_.laws));
}

void SoundBoard::update(double playback_time) {
  due_.clear();
  if (armed_) schedule_.advance(playback_time, due_);
  for (const DueCue& d : due_) {
    const auto delay = static_cast<std::uint32_t>(std::lround(d.delay * options_.rate));
    mixer_.start(bank_.pick(d.cue), static_cast<float>(d.cue.amplitude), delay);
  }
  pump();
}

void SoundBoard::pump() {
  for (std::size_t wanted = sink_->framesWanted(); wanted >= block_.size();
       wanted -= block_.size()) {
    mixer_.mix(block_);
    sink_->write(block_);
  }
}

}  // namespace pool::audio
