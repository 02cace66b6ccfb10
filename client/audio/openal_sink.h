// The OpenAL output: one source streaming a queue of mono 16-bit buffers.
#pragma once

#include <AL/al.h>
#include <AL/alc.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "client/audio/audio_sink.h"
#include "core/result.h"

namespace pool::audio {

/// Streams blocks to the default OpenAL device. The caller tops the queue up (framesWanted,
/// write) from its own loop: there is no audio thread of ours, no lock, and write() allocates
/// nothing. An underrun (the loop stalled) restarts the source at the next write.
class OpenAlSink : public AudioSink {
 public:
  /// Opens the default device; fails with a one-line reason when there is none.
  static Result<std::unique_ptr<OpenAlSink>> open(const SinkOptions& options);
  ~OpenAlSink() override;
  OpenAlSink(const OpenAlSink&) = delete;
  OpenAlSink& operator=(const OpenAlSink&) = delete;

  std::size_t framesWanted() override;
  void write(std::span<const float> block) override;
  std::size_t blockFrames() const override { return block_; }
  bool silent() const override { return false; }
  std::string name() const override { return "OpenAL: " + device_name_; }

  /// Source restarts after running dry.
  int underruns() const { return underruns_; }

 private:
  explicit OpenAlSink(const SinkOptions& options);

  int rate_;
  std::size_t block_;
  ALCdevice* device_ = nullptr;
  ALCcontext* context_ = nullptr;
  ALuint source_ = 0;
  std::vector<ALuint> buffers_;
  std::vector<ALuint> free_;       ///< buffers not queued (capacity reserved)
  std::vector<std::int16_t> pcm_;  ///< one block converted
  std::string device_name_;
  bool started_ = false;
  int underruns_ = 0;
};

}  // namespace pool::audio
