// Outputs: the silent sink keeps time; OpenAL opens or falls back silently with one log line,
// in process and in pool-sound, on machines with no sound hardware.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "client/audio/audio_sink.h"
#include "scenario/process_runner.h"

namespace pool::audio {
namespace {

using scenario::testing::runProcess;

const std::string kSound = std::string(POOL_BIN_DIR) + "/pool-sound";

TEST(SilentSink, TakesSamplesAtItsRateInWholeBlocks) {
  double now = 10.0;
  SilentSink sink(48000, 512, [&] { return now; });
  EXPECT_TRUE(sink.silent());
  EXPECT_EQ(sink.framesWanted(), 0u);
  now += 0.1;  // 4800 frames: 9 whole blocks
  EXPECT_EQ(sink.framesWanted(), 9u * 512u);
  const std::vector<float> block(512, 0.0f);
  for (int i = 0; i < 9; ++i) sink.write(block);
  EXPECT_EQ(sink.framesWanted(), 0u);
  now += 0.01;  // 480 more: 4800 + 480 - 4608 = 672 pending, one block
  EXPECT_EQ(sink.framesWanted(), 512u);
}

TEST(SilentSink, AStalledCallerIsNotAskedForTheWholeStall) {
  double now = 0.0;
  SilentSink sink(48000, 512, [&] { return now; });
  now = 60.0;
  EXPECT_LE(sink.framesWanted(), 12000u);
  EXPECT_GT(sink.framesWanted(), 11000u);
}

TEST(OpenSink, MutedGivesTheSilentSinkAndSaysSo) {
  std::vector<std::string> lines;
  SinkOptions options;
  options.mute = true;
  auto sink = openSink(options, [&](const std::string& l) { lines.push_back(l); });
  ASSERT_TRUE(sink);
  EXPECT_TRUE(sink->silent());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "sound: muted");
}

TEST(OpenSink, OpenAlOpensOrFallsBackAndEitherWayTakesSamples) {
  // OpenAL reads its drivers once per process: this is the only in-process device test.
  setenv("ALSOFT_DRIVERS", "null", 0);
  std::vector<std::string> lines;
  auto sink = openSink(SinkOptions{}, [&](const std::string& l) { lines.push_back(l); });
  ASSERT_TRUE(sink);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("sound: ", 0), 0u);
  EXPECT_EQ(sink->silent(), lines[0].find("playing silently") != std::string::npos);
  // Feed it for a while: a device (even the null one) or the silent clock keeps asking.
  const std::vector<float> block(sink->blockFrames(), 0.0f);
  std::size_t written = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (written < 48000 && std::chrono::steady_clock::now() < deadline) {
    for (std::size_t n = sink->framesWanted(); n >= block.size(); n -= block.size()) {
      sink->write(block);
      written += block.size();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_GE(written, 48000u) << sink->name();
}

/// Lines of `text` that start with `prefix`.
int linesStartingWith(const std::string& text, const std::string& prefix) {
  int n = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\n', at);
    if (text.compare(at, prefix.size(), prefix) == 0) ++n;
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return n;
}

TEST(PoolSound, PlaysSilentlyWithOneLineWhenThereIsNoDriver) {
  const auto r = runProcess({"/usr/bin/env", "ALSOFT_DRIVERS=no-such-driver", kSound, "break",
                             "--play", "--seconds", "0.5"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "sound: no audio device could be opened; playing silently\n");
  EXPECT_NE(r.out.find("on silent"), std::string::npos) << r.out;
}

TEST(PoolSound, PlaysOnOpenAlsNullDevice) {
  const auto r = runProcess(
      {"/usr/bin/env", "ALSOFT_DRIVERS=null", kSound, "break", "--play", "--seconds", "0.5"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(linesStartingWith(r.err, "sound: "), 1) << r.err;
  EXPECT_NE(r.out.find("played "), std::string::npos) << r.out;
}

TEST(PoolSound, MuteOpensNoDevice) {
  const auto r = runProcess({kSound, "break", "--play", "--mute", "--seconds", "0.2"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "sound: muted\n");
}

TEST(PoolSound, BadInputGetsOneLineAndWritesNothing) {
  const std::string wav = ::testing::TempDir() + "pool_sound_bad.wav";
  std::remove(wav.c_str());
  auto r = runProcess({kSound, "no_such_scene", "--wav", wav});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(linesStartingWith(r.err, "pool-sound: "), 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(std::fopen(wav.c_str(), "rb"), nullptr);
  r = runProcess({kSound, "break", "--wav", "/no/such/dir/x.wav"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err, "pool-sound: /no/such/dir/x.wav: cannot open for writing\n");
  r = runProcess({kSound, "break"});
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace pool::audio
