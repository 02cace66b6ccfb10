// The instant replay plays the last shot's frames again on the caller's clock, at real speed or
// slower, ends after the table at rest, and gives way to a new shot's frames.
#include "client/app/instant_replay.h"

#include <gtest/gtest.h>

namespace pool::app::test {
namespace {

/// Frame `k` of shot `shot` at 10 Hz: the cue ball at x = t (1 m/s along x), the 1 at rest.
client::TableFrame frameOf(std::uint32_t shot, std::uint32_t k) {
  client::TableFrame f;
  f.match = "m-1";
  f.shot_number = shot;
  f.frame = k;
  f.sim_time = 0.1 * k;
  physics::Ball cue;
  cue.id = 0;
  cue.pos = physics::Vec3(f.sim_time, 0.0, 0.028575);
  physics::Ball one;
  one.id = 1;
  one.pos = physics::Vec3(0.5, 0.3, 0.028575);
  f.balls = {cue, one};
  return f;
}

/// A replay holding shot 3: one second of frames (0 to 1.0 s).
InstantReplay kept() {
  InstantReplay replay;
  for (std::uint32_t k = 0; k <= 10; ++k) replay.record(frameOf(3, k));
  return replay;
}

TEST(InstantReplay, NothingKeptNothingToReplay) {
  InstantReplay replay;
  EXPECT_FALSE(replay.shot());
  EXPECT_FALSE(replay.start(1.0));
  EXPECT_FALSE(replay.playing());
  EXPECT_FALSE(replay.sample(1.5));
  replay.record(frameOf(1, 0));
  EXPECT_FALSE(replay.shot()) << "one frame is no motion to replay";
}

TEST(InstantReplay, PlaysTheShotAgainAtRealSpeedThenGivesTheLiveTableBack) {
  InstantReplay replay = kept();
  ASSERT_EQ(replay.shot(), 3u);
  ASSERT_TRUE(replay.start(20.0));
  for (const double t : {0.0, 0.25, 0.55, 0.999}) {
    const auto balls = replay.sample(20.0 + t);
    ASSERT_TRUE(balls) << t;
    EXPECT_NEAR((*balls)[0].pos.x(), t, 1e-9) << "the cue ball at 1 m/s";
    EXPECT_NEAR((*balls)[1].pos.y(), 0.3, 1e-12);
    EXPECT_NEAR(replay.replayTime(), t, 1e-9);
  }
  // The table at rest is held a moment, then the replay ends by itself.
  const auto rest = replay.sample(20.0 + 1.0 + InstantReplay::kHold / 2);
  ASSERT_TRUE(rest);
  EXPECT_NEAR((*rest)[0].pos.x(), 1.0, 1e-12);
  EXPECT_FALSE(replay.sample(20.0 + 1.0 + InstantReplay::kHold + 0.01));
  EXPECT_FALSE(replay.playing());
  EXPECT_EQ(replay.shot(), 3u) << "kept for another replay";
  EXPECT_TRUE(replay.start(30.0));
}

TEST(InstantReplay, SlowMotionStretchesTheShot) {
  InstantReplay replay = kept();
  ASSERT_TRUE(replay.start(5.0, 0.4));
  const auto balls = replay.sample(6.0);  // 1 s of the clock: 0.4 s of the shot
  ASSERT_TRUE(balls);
  EXPECT_NEAR((*balls)[0].pos.x(), 0.4, 1e-9);
  EXPECT_TRUE(replay.sample(5.0 + 1.0 / 0.4 - 0.01)) << "still replaying near the shot's end";
  EXPECT_FALSE(replay.sample(5.0 + (1.0 + InstantReplay::kHold) / 0.4 + 0.01));
}

TEST(InstantReplay, ANewShotsFrameEndsTheReplayAndReplacesTheShot) {
  InstantReplay replay = kept();
  ASSERT_TRUE(replay.start(0.0));
  ASSERT_TRUE(replay.sample(0.3));
  replay.record(frameOf(4, 0));
  EXPECT_FALSE(replay.playing()) << "the live game moves on";
  EXPECT_FALSE(replay.sample(0.4));
  EXPECT_FALSE(replay.shot()) << "shot 4 has one frame so far";
  replay.record(frameOf(4, 1));
  EXPECT_EQ(replay.shot(), 4u);
  replay.record(frameOf(3, 7));  // a late frame of the old shot changes nothing
  EXPECT_EQ(replay.shot(), 4u);
  replay.clear();
  EXPECT_FALSE(replay.shot());
}

}  // namespace
}  // namespace pool::app::test
