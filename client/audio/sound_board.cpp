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

std::unique_ptr<AudioSink> openFor(const SoundOptions& o) {
  auto log = o.log ? o.log : [](const std::string& line) { std::cerr << line << '\n'; };
  return openSink(sinkOptionsOf(o), log);
}

}  // namespace

SoundBoard::SoundBoard(const SoundOptions& options) : SoundBoard(options, openFor(options)) {}

SoundBoard::SoundBoard(const SoundOptions& options, std::unique_ptr<AudioSink> sink)
    : options_(options),
      bank_(options.rate),
      mixer_(mixerOptionsOf(options)),
      schedule_(options.schedule),
      sink_(std::move(sink)) {
  if (!sink_) sink_ = std::make_unique<SilentSink>(options.rate, options.sink.block);
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
  events_key_ = shot_key;
  frames_key_.reset();
  schedule_.setShot(cuesFromEvents(events, options_.laws), shot_key);
}

void SoundBoard::onFrame(std::uint64_t shot_key, double sim_time,
                         const std::vector<physics::Ball>& balls) {
  if (stale(shot_key)) return;
  if (shot_key != 0 && events_key_ == shot_key) return;  // the exact log drives this shot
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
  schedule_.advance(playback_time, due_);
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
