// The sound board end to end: a shot's events in, one update per frame, mixed sound out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "audio/shots.h"
#include "client/audio/sound_board.h"

namespace pool::audio {
namespace {

using physics::EventType;

/// An output that records everything and takes 800 frames (1/60 s at 48 kHz) per update.
class CaptureSink : public AudioSink {
 public:
  explicit CaptureSink(std::vector<float>& out) : out_(out) {}
  std::size_t framesWanted() override {
    credit_ += 800;
    return credit_ - credit_ % kBlock;
  }
  void write(std::span<const float> block) override {
    out_.insert(out_.end(), block.begin(), block.end());
    credit_ -= block.size();
  }
  std::size_t blockFrames() const override { return kBlock; }
  bool silent() const override { return false; }
  std::string name() const override { return "capture"; }

 private:
  static constexpr std::size_t kBlock = 256;
  std::vector<float>& out_;
  std::size_t credit_ = 0;
};

constexpr double kFrame = 1.0 / 60.0;

std::size_t audibleCues(const physics::EventLog& events) {
  return cuesFromEvents(events, ImpactLaws{}).size();
}

/// Frames from `from` to `to` s of playback, one update each; returns the last frame's time.
double play(SoundBoard& board, double from, double to) {
  double t = from;
  for (int i = 0; from + i * kFrame <= to; ++i) board.update(t = from + i * kFrame);
  return t;
}

TEST(SoundBoard, PlaysABreakThroughItsOutputUnderFullScale) {
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  const auto& events = test::breakEvents();
  board.onShot(events, 1);
  board.onFrame(1, 0.0, {});  // the shot's first frame
  play(board, 0.0, events.back().t + 1.5);
  const auto& stats = board.mixerStats();
  EXPECT_EQ(stats.started + stats.dropped, audibleCues(events));
  EXPECT_EQ(board.schedule().pending(), 0u);
  ASSERT_FALSE(heard.empty());
  float peak = 0.0f;
  for (float s : heard) peak = std::max(peak, std::fabs(s));
  EXPECT_LT(peak, 1.0f);
  EXPECT_GT(test::rms(heard), 0.005);
}

TEST(SoundBoard, ASoundStartsInTheAudioAtItsEventTime) {
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  board.onShot({test::event(EventType::BallBall, 0.5, 2.0)}, 0);  // no key: sounds at once
  play(board, 0.0, 1.0);
  const auto first = std::find_if(heard.begin(), heard.end(), [](float s) { return s != 0.0f; });
  ASSERT_NE(first, heard.end());
  const double at = static_cast<double>(first - heard.begin()) / kDefaultSampleRate;
  // Within a frame and a block of the event (the output runs a frame behind the updates).
  EXPECT_NEAR(at, 0.5, 2 * kFrame);
}

TEST(SoundBoard, ASpectatorJoiningMidShotHearsOnlyWhatFollows) {
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  const auto& events = test::breakEvents();
  const auto cues = cuesFromEvents(events, ImpactLaws{});
  const double join = 1.0;
  const auto before = static_cast<std::size_t>(
      std::count_if(cues.begin(), cues.end(), [&](const SoundCue& c) { return c.t < join - 0.1; }));
  ASSERT_GT(before, 20u);
  board.onShot(events, 9);
  board.onFrame(9, join, {});  // the first frame this spectator sees
  board.update(join);
  EXPECT_EQ(board.schedule().skipped(), before);
  EXPECT_LT(board.mixerStats().started + board.mixerStats().dropped, 10u);
  play(board, join, events.back().t + 0.5);
  EXPECT_EQ(board.mixerStats().started + board.mixerStats().dropped, cues.size() - before);
}

TEST(SoundBoard, ANewShotCutsOffTheOldAndARepeatedReportIsIgnored) {
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  const auto& events = test::breakEvents();
  board.onShot(events, 1);
  board.onFrame(1, 0.0, {});
  play(board, 0.0, 0.5);
  board.onShot(events, 1);  // delivered again: nothing restarts
  const double reached = play(board, 0.5, 0.8);
  const auto sounded = board.mixerStats().started + board.mixerStats().dropped;
  const auto cues = cuesFromEvents(events, ImpactLaws{});
  EXPECT_EQ(sounded,
            static_cast<std::size_t>(std::count_if(
                cues.begin(), cues.end(), [&](const SoundCue& c) { return c.t <= reached; })));
  ASSERT_LT(sounded, cues.size());
  board.onShot({test::event(EventType::Strike, 0.0, 3.0, 0)}, 2);
  board.onFrame(2, 0.0, {});
  play(board, 0.0, 3.0);
  EXPECT_EQ(board.mixerStats().started + board.mixerStats().dropped, sounded + 1);
}

std::size_t sounded(const SoundBoard& board) {
  return board.mixerStats().started + board.mixerStats().dropped;
}

TEST(SoundBoard, FramesSoundAShotAndItsLogArrivingAfterwardsAddsNothing) {
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  const auto shot = test::framedShot("straight_pocket");
  for (const auto& frame : shot.trajectory) {
    board.onFrame(5, frame.t, frame.balls);
    board.update(frame.t);
  }
  // The strike, the click and the drop, heard as the frames played.
  EXPECT_EQ(sounded(board), 3u);
  board.onShot(shot.events, 5);  // the server's log, after the last frame
  play(board, shot.trajectory.back().t, shot.trajectory.back().t + 1.0);
  EXPECT_EQ(sounded(board), 3u);
  board.onShot(shot.events, 4);  // an older shot's log: stale
  play(board, 0.0, 1.0);
  EXPECT_EQ(sounded(board), 3u);
}

TEST(SoundBoard, TheReportOfAShotAlreadyOverStaysSilent) {
  // A spectator joins between shots and receives the last shot's report: no frames follow.
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  const auto& events = test::breakEvents();
  board.onShot(events, 12);
  play(board, 0.0, events.back().t + 1.0);
  EXPECT_EQ(sounded(board), 0u);
  EXPECT_EQ(test::rms(heard), 0.0);
  // The next shot's frames sound as usual.
  const auto shot = test::framedShot("straight_pocket");
  for (const auto& frame : shot.trajectory) {
    board.onFrame(13, frame.t, frame.balls);
    board.update(frame.t);
  }
  EXPECT_EQ(sounded(board), 3u);
}

TEST(SoundBoard, AShotWhoseLogCameFirstIgnoresItsFrames) {
  std::vector<float> heard;
  SoundBoard board({}, std::make_unique<CaptureSink>(heard));
  const auto shot = test::framedShot("straight_pocket");
  board.onShot(shot.events, 6);
  for (const auto& frame : shot.trajectory) {
    board.onFrame(6, frame.t, frame.balls);
    board.update(frame.t);
  }
  play(board, shot.trajectory.back().t, shot.trajectory.back().t + 1.0);
  EXPECT_EQ(sounded(board), audibleCues(shot.events));
  // The next shot's frames take over.
  const auto& first = shot.trajectory.front();
  board.onFrame(7, first.t, first.balls);
  board.update(first.t);
  EXPECT_EQ(sounded(board), audibleCues(shot.events) + 1);  // its strike
}

TEST(SoundBoard, MutedItIsSilentSaysSoOnceAndStillWorks) {
  SoundOptions options;
  options.mute = true;
  std::vector<std::string> lines;
  options.log = [&](const std::string& l) { lines.push_back(l); };
  SoundBoard board(options);
  EXPECT_TRUE(board.silent());
  EXPECT_EQ(board.outputName(), "silent");
  board.onShot({test::event(EventType::Strike, 0.0, 3.0, 0)}, 0);
  play(board, 0.0, 0.2);
  EXPECT_EQ(board.mixerStats().started, 1u);
  EXPECT_EQ(lines, std::vector<std::string>{"sound: muted"});
}

}  // namespace
}  // namespace pool::audio

namespace pool::audio {
namespace {

TEST(SoundBoard, SettingsOutOfRangeFallBackWithOneLineEach) {
  SoundOptions options;
  options.mute = true;
  options.rate = 0;
  options.mixer.voices = -3;
  std::vector<std::string> lines;
  options.log = [&](const std::string& l) { lines.push_back(l); };
  SoundBoard board(options);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "sound: sample rate (Hz) 0 is outside [8000, 192000]; using 48000");
  EXPECT_EQ(lines[1], "sound: voices -3 is outside [1, 256]; using 24");
  EXPECT_EQ(lines[2], "sound: muted");
  EXPECT_EQ(board.bank().rate(), kDefaultSampleRate);
  board.onShot({test::event(physics::EventType::Strike, 0.0, 3.0, 0)}, 0);
  board.update(0.0);
  EXPECT_EQ(board.mixerStats().started, 1u);
}

}  // namespace
}  // namespace pool::audio
