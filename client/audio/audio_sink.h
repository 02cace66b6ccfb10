// Where mixed sound goes: an output device, or a silent sink that keeps time like one.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace pool::audio {

/// A destination for mono samples in (-1, 1), taken in blocks. Never blocks.
class AudioSink {
 public:
  virtual ~AudioSink() = default;
  /// Frames the sink would take now (a multiple of blockFrames()).
  virtual std::size_t framesWanted() = 0;
  /// Takes one block of blockFrames() samples.
  virtual void write(std::span<const float> block) = 0;
  virtual std::size_t blockFrames() const = 0;
  /// True when nothing is heard (no device, or muted).
  virtual bool silent() const = 0;
  /// What plays the sound, for logs: "OpenAL: <device>" or "silent".
  virtual std::string name() const = 0;
};

/// Plays nothing but consumes samples at `rate` per second of its clock, as a device would, so
/// that voices advance and end. Falls behind by at most a quarter second (then skips ahead).
class SilentSink : public AudioSink {
 public:
  using Clock = std::function<double()>;  ///< s, monotonic
  explicit SilentSink(int rate, std::size_t block = 512, Clock clock = {});

  std::size_t framesWanted() override;
  void write(std::span<const float> block) override;
  std::size_t blockFrames() const override { return block_; }
  bool silent() const override { return true; }
  std::string name() const override { return "silent"; }

 private:
  int rate_;
  std::size_t block_;
  Clock clock_;
  double start_;
  std::size_t written_ = 0;
};

/// How to open the output.
struct SinkOptions {
  bool mute = false;        ///< never open a device
  int rate = 48000;         ///< Hz
  std::size_t block = 512;  ///< frames per block (≈ 11 ms at 48 kHz)
  int blocks = 6;           ///< blocks queued on the device (latency vs. safety against hitches)
};

/// The OpenAL output, or, when muted or when no device can be opened (no sound card, no sound
/// server, ALSOFT_DRIVERS naming no usable driver), a SilentSink. Logs one line saying which
/// through `log`.
std::unique_ptr<AudioSink> openSink(const SinkOptions& options,
                                    const std::function<void(const std::string&)>& log);

}  // namespace pool::audio
