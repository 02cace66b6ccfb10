// The scheduler: each cue once, when playback reaches it; skipped frames, late joins, new shots.
#include <gtest/gtest.h>

#include <map>

#include "client/audio/cue_schedule.h"

namespace pool::audio {
namespace {

/// Cues at the given times, each with its index as its ball (to tell them apart).
std::vector<SoundCue> cuesAt(const std::vector<double>& times) {
  std::vector<SoundCue> cues;
  for (std::size_t i = 0; i < times.size(); ++i) {
    cues.push_back({times[i], SoundKind::BallClick, 0.01, 1.0, static_cast<int>(i)});
  }
  return cues;
}

/// Every cue started, by ball, with the playback time of the update that started it.
struct Started {
  std::map<int, int> count;
  std::map<int, double> at;
  std::vector<double> delays;
};

void advance(CueSchedule& s, double t, Started& out) {
  std::vector<DueCue> due;
  s.advance(t, due);
  for (const auto& d : due) {
    ++out.count[d.cue.ball];
    out.at[d.cue.ball] = t;
    out.delays.push_back(d.delay);
  }
}

const std::vector<double> kTimes = {0.0, 0.004, 0.0041, 0.05, 0.2, 0.2, 0.35, 1.0, 1.7, 2.5};

TEST(CueSchedule, EveryCueStartsOnceAtTheFirstFrameThatReachesIt) {
  CueSchedule s;
  s.setShot(cuesAt(kTimes));
  Started started;
  const double dt = 1.0 / 60.0;
  for (int frame = 0; frame * dt < 3.0; ++frame) advance(s, frame * dt, started);
  ASSERT_EQ(started.count.size(), kTimes.size());
  for (std::size_t i = 0; i < kTimes.size(); ++i) {
    const int ball = static_cast<int>(i);
    EXPECT_EQ(started.count[ball], 1) << "cue " << i;
    // Started by the first frame at or after its time, and not earlier.
    EXPECT_GE(started.at[ball], kTimes[i]) << "cue " << i;
    EXPECT_LT(started.at[ball] - kTimes[i], dt + 1e-9) << "cue " << i;
  }
  for (double d : started.delays) {
    EXPECT_GE(d, 0.0);
    EXPECT_LE(d, dt + 1e-9);
  }
  EXPECT_EQ(s.pending(), 0u);
  EXPECT_EQ(s.skipped(), 0u);
}

TEST(CueSchedule, SkippedFramesLoseNothingAndKeepTheSpacingWithinTheSpread) {
  ScheduleOptions options;
  options.max_spread = 0.05;
  CueSchedule s(options);
  s.setShot(cuesAt(kTimes));
  Started started;
  // A frame at the strike, then the loop stalls for 0.9 s, then frames come again.
  for (double t : {0.0, 0.9, 0.91, 2.0, 4.0}) advance(s, t, started);
  ASSERT_EQ(started.count.size(), kTimes.size());
  for (const auto& [ball, n] : started.count) EXPECT_EQ(n, 1) << "cue " << ball;
  EXPECT_EQ(started.at[3], 0.9);  // the cue at 0.05 waited for the stalled frame
  for (double d : started.delays) EXPECT_LE(d, options.max_spread + 1e-12);
}

TEST(CueSchedule, ALateJoinSkipsWhatHappenedBefore) {
  ScheduleOptions options;
  options.late_window = 0.1;
  CueSchedule s(options);
  s.setShot(cuesAt(kTimes));
  Started started;
  // A spectator's first frame of this shot is at 1.05 s: the cue at 1.0 is within the window.
  for (double t = 1.05; t < 3.0; t += 1.0 / 60.0) advance(s, t, started);
  EXPECT_EQ(started.count.size(), 3u);
  EXPECT_EQ(started.count[7], 1);  // t = 1.0
  EXPECT_EQ(started.count[8], 1);
  EXPECT_EQ(started.count[9], 1);
  EXPECT_EQ(started.count.count(0), 0u);
  EXPECT_EQ(s.skipped(), 7u);
}

TEST(CueSchedule, ANewShotCutsOffTheOldOnesRemainingCues) {
  CueSchedule s;
  s.setShot(cuesAt(kTimes), 41);
  Started first;
  for (double t = 0.0; t < 0.5; t += 1.0 / 60.0) advance(s, t, first);
  EXPECT_EQ(first.count.size(), 7u);  // up to the cue at 0.35

  // The next shot's cues are marked apart by an offset ball number.
  auto next = cuesAt({0.0, 0.3});
  for (auto& c : next) c.ball += 100;
  s.setShot(next, 42);
  Started second;
  for (double t = 0.0; t < 3.0; t += 1.0 / 60.0) advance(s, t, second);
  ASSERT_EQ(second.count.size(), 2u);
  EXPECT_EQ(second.count[100], 1);
  EXPECT_EQ(second.count[101], 1);
}

TEST(CueSchedule, TheSameShotAgainIsNotReplayedAndTimeGoingBackStartsNothing) {
  CueSchedule s;
  s.setShot(cuesAt(kTimes), 7);
  Started started;
  for (double t = 0.0; t < 0.5; t += 1.0 / 60.0) advance(s, t, started);
  s.setShot(cuesAt(kTimes), 7);  // the same report delivered again
  advance(s, 0.1, started);      // and a frame from the past
  advance(s, std::nan(""), started);
  for (double t = 0.5; t < 3.0; t += 1.0 / 60.0) advance(s, t, started);
  ASSERT_EQ(started.count.size(), kTimes.size());
  for (const auto& [ball, n] : started.count) EXPECT_EQ(n, 1) << "cue " << ball;
}

TEST(CueSchedule, NoShotNoCues) {
  CueSchedule s;
  Started started;
  advance(s, 1.0, started);
  s.setShot({});
  advance(s, 2.0, started);
  EXPECT_TRUE(started.count.empty());
}

}  // namespace
}  // namespace pool::audio
