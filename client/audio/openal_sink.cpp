// Opens the default OpenAL device and keeps a source's buffer queue topped up.
#include "client/audio/openal_sink.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace pool::audio {
namespace {

/// Opens the default device with stderr muted: the sound libraries print several lines each
/// when there is no card or server, and the caller logs the outcome in one line.
ALCdevice* openQuietly() {
  setenv("ALSOFT_LOGLEVEL", "0", 0);
  const int saved = dup(STDERR_FILENO);
  const int devnull = ::open("/dev/null", O_WRONLY);
  if (saved >= 0 && devnull >= 0) dup2(devnull, STDERR_FILENO);
  ALCdevice* device = alcOpenDevice(nullptr);
  if (saved >= 0 && devnull >= 0) dup2(saved, STDERR_FILENO);
  if (devnull >= 0) close(devnull);
  if (saved >= 0) close(saved);
  return device;
}

}  // namespace

OpenAlSink::OpenAlSink(const SinkOptions& options)
    : rate_(options.rate), block_(std::max<std::size_t>(1, options.block)) {}

Result<std::unique_ptr<OpenAlSink>> OpenAlSink::open(const SinkOptions& options) {
  using R = Result<std::unique_ptr<OpenAlSink>>;
  std::unique_ptr<OpenAlSink> sink(new OpenAlSink(options));
  sink->device_ = openQuietly();
  if (!sink->device_) return R::fail("no audio device could be opened");
  sink->context_ = alcCreateContext(sink->device_, nullptr);
  if (!sink->context_ || !alcMakeContextCurrent(sink->context_)) {
    return R::fail("the audio device gave no OpenAL context");
  }
  const ALCchar* name = alcGetString(sink->device_, ALC_DEVICE_SPECIFIER);
  sink->device_name_ = name ? name : "default";
  alGetError();
  alGenSources(1, &sink->source_);
  const int count = std::max(2, options.blocks);
  sink->buffers_.resize(static_cast<std::size_t>(count));
  alGenBuffers(count, sink->buffers_.data());
  if (alGetError() != AL_NO_ERROR) return R::fail("OpenAL could not make a source and buffers");
  alSourcef(sink->source_, AL_GAIN, 1.0f);
  alSourcei(sink->source_, AL_SOURCE_RELATIVE, AL_TRUE);  // no 3-D placement: a plain stream
  sink->free_ = sink->buffers_;
  sink->pcm_.resize(sink->block_);
  return R::ok(std::move(sink));
}

OpenAlSink::~OpenAlSink() {
  if (source_) {
    alSourceStop(source_);
    alSourcei(source_, AL_BUFFER, 0);
    alDeleteSources(1, &source_);
  }
  if (!buffers_.empty()) alDeleteBuffers(static_cast<ALsizei>(buffers_.size()), buffers_.data());
  if (context_) {
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(context_);
  }
  if (device_) alcCloseDevice(device_);
}

std::size_t OpenAlSink::framesWanted() {
  ALint processed = 0;
  alGetSourcei(source_, AL_BUFFERS_PROCESSED, &processed);
  while (processed-- > 0) {
    ALuint done = 0;
    alSourceUnqueueBuffers(source_, 1, &done);
    free_.push_back(done);  // never grows past the reserved buffer count
  }
  return free_.size() * block_;
}

void OpenAlSink::write(std::span<const float> block) {
  if (free_.empty() || block.size() != block_) return;
  for (std::size_t i = 0; i < block_; ++i) {
    pcm_[i] = static_cast<std::int16_t>(std::lround(std::clamp(block[i], -1.0f, 1.0f) * 32767.0f));
  }
  const ALuint buffer = free_.back();
  free_.pop_back();
  alBufferData(buffer, AL_FORMAT_MONO16, pcm_.data(),
               static_cast<ALsizei>(block_ * sizeof(std::int16_t)), rate_);
  alSourceQueueBuffers(source_, 1, &buffer);
  ALint state = 0;
  alGetSourcei(source_, AL_SOURCE_STATE, &state);
  if (state != AL_PLAYING) {
    if (started_) ++underruns_;
    started_ = true;
    alSourcePlay(source_);
  }
}

}  // namespace pool::audio
