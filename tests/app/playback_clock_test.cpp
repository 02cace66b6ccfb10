// 30 Hz snapshots played back at 60 and 144 frames per second: no backward step, velocity close to
// the true motion's, also across a dropped snapshot.
#include "client/app/playback_clock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pool::app::test {
namespace {

// The true motion: ball 1 slows down along +x (sliding to rest at t = 1.5 s), ball 2 curves.
constexpr double kV0 = 3.0, kDecel = 2.0, kStop = kV0 / kDecel;

Eigen::Vector3d positionOf(int id, double t) {
  const double s = std::min(t, kStop);
  if (id == 1) return {-1.0 + kV0 * s - kDecel * s * s / 2, 0.0, 0.028575};
  return {0.5 * std::sin(1.2 * s), 0.4 * std::cos(1.2 * s), 0.028575};
}

Eigen::Vector3d velocityOf(int id, double t) {
  if (t >= kStop) return Eigen::Vector3d::Zero();
  if (id == 1) return {kV0 - kDecel * t, 0.0, 0.0};
  return {0.6 * std::cos(1.2 * t), -0.48 * std::sin(1.2 * t), 0.0};
}

client::TableFrame frameAt(std::uint32_t n, double sim_time) {
  client::TableFrame frame;
  frame.match = "srv-1";
  frame.frame = n;
  frame.sim_time = sim_time;
  frame.shot_number = 4;
  for (int id : {1, 2}) {
    physics::Ball b;
    b.id = id;
    b.pos = positionOf(id, sim_time);
    b.vel = velocityOf(id, sim_time);
    frame.balls.push_back(b);
  }
  return frame;
}

struct Smoothness {
  double max_backward = 0.0;        ///< m: largest step against the true heading
  double max_velocity_error = 0.0;  ///< m/s: |shown velocity − true velocity|, worst case
  int samples = 0;
};

// Streams 30 Hz frames (arrival jitter up to 6 ms, frame `dropped` lost) and draws at `fps`.
Smoothness play(double fps, int dropped) {
  PlaybackClock clock;
  const double snapshot_dt = 1.0 / 30.0, latency = 0.02;
  std::vector<std::pair<double, client::TableFrame>> arrivals;
  for (std::uint32_t n = 0; n * snapshot_dt <= kStop + 0.2; ++n) {
    if (static_cast<int>(n) == dropped) continue;
    const double jitter = 0.006 * std::sin(n * 2.39996);  // deterministic, within ±6 ms
    arrivals.emplace_back(n * snapshot_dt + latency + jitter, frameAt(n, n * snapshot_dt));
  }
  Smoothness out;
  std::size_t next = 0;
  std::optional<std::vector<physics::Ball>> previous;
  double previous_play = 0.0;
  for (double now = latency; now < kStop + 0.5; now += 1.0 / fps) {
    while (next < arrivals.size() && arrivals[next].first <= now) {
      clock.push(arrivals[next].second, arrivals[next].first);
      ++next;
    }
    auto balls = clock.sample(now);
    if (!balls) continue;
    const double play = clock.playTime();
    // Only steady playback is judged: after the first frames, before the end of the stream.
    const bool judged = previous && previous_play > 0.1 && play < kStop - 0.05;
    for (std::size_t i = 0; judged && i < balls->size(); ++i) {
      const physics::Ball& b = (*balls)[i];
      const Eigen::Vector3d step = b.pos - (*previous)[i].pos;
      const Eigen::Vector3d truth = velocityOf(b.id, play);
      out.max_backward = std::max(out.max_backward, -step.dot(truth.normalized()));
      const Eigen::Vector3d shown = step * fps;
      out.max_velocity_error = std::max(out.max_velocity_error, (shown - truth).norm());
      ++out.samples;
    }
    previous = std::move(balls);
    previous_play = play;
  }
  return out;
}

// Error bound: a few percent of the top speed (3 m/s), well below what a frame held for a whole
// snapshot interval would show (the full speed).
constexpr double kVelocityTolerance = 0.1;  // m/s

TEST(PlaybackClockTest, ThirtyHertzAtSixtyFramesIsSmooth) {
  const Smoothness s = play(60.0, -1);
  EXPECT_GT(s.samples, 100);
  EXPECT_LE(s.max_backward, 1e-12);
  EXPECT_LT(s.max_velocity_error, kVelocityTolerance);
}

TEST(PlaybackClockTest, ThirtyHertzAt144FramesIsSmooth) {
  const Smoothness s = play(144.0, -1);
  EXPECT_GT(s.samples, 250);
  EXPECT_LE(s.max_backward, 1e-12);
  EXPECT_LT(s.max_velocity_error, kVelocityTolerance);
}

TEST(PlaybackClockTest, ADroppedSnapshotStaysSmooth) {
  for (double fps : {60.0, 144.0}) {
    const Smoothness s = play(fps, 20);
    EXPECT_LE(s.max_backward, 1e-12) << fps;
    EXPECT_LT(s.max_velocity_error, kVelocityTolerance) << fps;
  }
}

TEST(PlaybackClockTest, HoldingEachSnapshotWouldNotPass) {
  // The measure can fail: with the playback a whole snapshot late and no interpolation the shown
  // velocity swings between zero and double.
  client::SnapshotBuffer buffer(64);
  double worst = 0.0;
  Eigen::Vector3d previous = positionOf(1, 0.2);
  for (double now = 0.2; now < 1.0; now += 1.0 / 144.0) {
    const double held = std::floor(now * 30.0) / 30.0;
    buffer.push(frameAt(static_cast<std::uint32_t>(std::lround(held * 30.0)), held));
    const Eigen::Vector3d pos = buffer.sample(held)->at(0).pos;
    worst = std::max(worst, ((pos - previous) * 144.0 - velocityOf(1, now)).norm());
    previous = pos;
  }
  EXPECT_GT(worst, kVelocityTolerance);
}

TEST(PlaybackClockTest, ANewShotStartsItsOwnPlayback) {
  PlaybackClock clock;
  clock.push(frameAt(0, 0.0), 10.0);
  clock.push(frameAt(30, 1.0), 11.0);
  ASSERT_TRUE(clock.sample(11.5));
  EXPECT_GT(clock.playTime(), 1.0);
  auto next = frameAt(0, 0.0);
  next.shot_number = 5;
  clock.push(next, 20.0);
  ASSERT_TRUE(clock.sample(20.05));
  EXPECT_LT(clock.playTime(), 0.01);
  EXPECT_EQ(clock.shot(), 5u);
}

TEST(PlaybackClockTest, AShotEndsWhenPlayedOutAndCountedByAState) {
  PlaybackClock clock;
  EXPECT_FALSE(clock.inMotion(0));
  clock.push(frameAt(0, 0.0), 10.0);
  clock.push(frameAt(30, 1.0), 11.0);  // shot 4 (frameAt's), one second of motion
  ASSERT_TRUE(clock.sample(10.5));
  EXPECT_TRUE(clock.inMotion(4));  // the state came first, the playback is still going
  ASSERT_TRUE(clock.sample(12.0));
  EXPECT_TRUE(clock.caughtUp());
  EXPECT_TRUE(clock.inMotion(3));   // played out, but no state counts the shot yet
  EXPECT_FALSE(clock.inMotion(4));  // played out and counted
}

}  // namespace
}  // namespace pool::app::test
