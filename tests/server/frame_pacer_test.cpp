// Frames come out when the clock reaches their simulated time, or all at once unpaced.
#include <gtest/gtest.h>

#include "server/match/frame_pacer.h"

namespace pool::server {
namespace {

TEST(FramePacer, HandsOutFramesAsTheClockReachesThem) {
  FramePacer pacer({0.0, 0.5, 1.0, 1.2}, 10.0, false);
  EXPECT_EQ(pacer.nextDue(), 10.0);
  FrameRange r = pacer.take(9.99);
  EXPECT_TRUE(r.empty());
  r = pacer.take(10.0);
  EXPECT_EQ(r.first, 0u);
  EXPECT_EQ(r.end, 1u);
  EXPECT_EQ(pacer.nextDue(), 10.5);
  r = pacer.take(11.1);  // late: both due frames at once
  EXPECT_EQ(r.first, 1u);
  EXPECT_EQ(r.end, 3u);
  EXPECT_FALSE(pacer.done());
  r = pacer.take(11.2);
  EXPECT_EQ(r.size(), 1u);
  EXPECT_TRUE(pacer.done());
  EXPECT_FALSE(pacer.nextDue());
  EXPECT_TRUE(pacer.take(100.0).empty());
}

TEST(FramePacer, UnpacedHandsOutEverythingAtTheStart) {
  FramePacer pacer({0.0, 0.5, 1.0}, 3.0, true);
  EXPECT_EQ(pacer.nextDue(), 3.0);
  const FrameRange r = pacer.take(3.0);
  EXPECT_EQ(r.size(), 3u);
  EXPECT_TRUE(pacer.done());
}

TEST(FramePacer, NoFramesIsDoneAtOnce) {
  FramePacer pacer({}, 0.0, false);
  EXPECT_TRUE(pacer.done());
  EXPECT_FALSE(pacer.nextDue());
}

}  // namespace
}  // namespace pool::server
