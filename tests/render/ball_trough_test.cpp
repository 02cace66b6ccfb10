// The pocketed-ball trough: pocketing order, balls leaving it, where its slots are, and a snooker
// set's 22.
#include "client/render/ball_trough.h"

#include <gtest/gtest.h>

#include "client/render/scene.h"

namespace pool::render {
namespace {

class BallTroughTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto s = rackScene();
    ASSERT_TRUE(static_cast<bool>(s)) << s.error();
    scene_ = std::move(*s);
  }
  std::vector<SceneBall> withPocketed(std::initializer_list<int> ids) const {
    std::vector<SceneBall> balls = scene_.balls;
    for (SceneBall& b : balls) {
      for (int id : ids) b.pocketed = b.pocketed || b.id == id;
    }
    return balls;
  }
  Scene scene_;
};

TEST_F(BallTroughTest, BallsQueueInThePocketingOrder) {
  BallTrough trough(scene_.geometry, scene_.ball_radius);
  trough.update(withPocketed({5}));
  trough.update(withPocketed({5, 12, 3}));
  EXPECT_EQ(trough.slotOf(5), 0);
  EXPECT_EQ(trough.slotOf(3), 1) << "two at once: by id";
  EXPECT_EQ(trough.slotOf(12), 2);
  EXPECT_FALSE(trough.slotOf(1).has_value());
}

TEST_F(BallTroughTest, ABallBackOnTheTableLeavesAndTheRowCloses) {
  BallTrough trough(scene_.geometry, scene_.ball_radius);
  trough.update(withPocketed({0, 7, 9}));
  trough.update(withPocketed({7, 9}));  // the cue ball was brought back
  EXPECT_FALSE(trough.slotOf(0).has_value());
  EXPECT_EQ(trough.slotOf(7), 0);
  EXPECT_EQ(trough.slotOf(9), 1);
}

TEST_F(BallTroughTest, SlotsLieOutsideTheTableUnderTheRailOneDiameterApart) {
  const BallTrough trough(scene_.geometry, scene_.ball_radius);
  const double r = scene_.ball_radius;
  for (int i = 0; i < 16; ++i) {
    const Eigen::Vector3d p = trough.slot(i);
    EXPECT_LT(p.y(), -scene_.geometry.width / 2.0 - r) << "beyond the near cushion";
    EXPECT_LT(p.z(), 0.0) << "below the slate";
    EXPECT_LT(std::abs(p.x()), scene_.geometry.length / 2.0);
    if (i > 0) {
      EXPECT_NEAR((p - trough.slot(i - 1)).norm(), 2.0 * r, 1e-12);
    }
  }
  EXPECT_GT(trough.slot(0).x(), trough.slot(15).x()) << "the first ball sits at the foot end";
}

// A snooker set: every ball of it (the cue ball and 1-21) pocketed at once has a slot, the row
// within the table's length and the channel's ends round it.
TEST(BallTroughSnookerTest, HoldsEverySnookerBall) {
  auto s = tableScene("snooker-12ft");
  ASSERT_TRUE(static_cast<bool>(s)) << s.error();
  ASSERT_EQ(s->ball_set, BallSet::Snooker);
  const int slots = troughSlotsFor(s->ball_set);
  EXPECT_EQ(slots, 22);
  EXPECT_EQ(troughSlotsFor(BallSet::Pool), 16);
  BallTrough trough(s->geometry, s->ball_radius, slots);
  std::vector<SceneBall> balls;
  for (int id = 0; id <= 21; ++id)
    balls.push_back({id, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(), true});
  trough.update(balls);
  const double r = s->ball_radius;
  double lo = 1e9, hi = -1e9;
  for (const auto& p : trough.mesh().positions) {
    lo = std::min(lo, double(p.x));
    hi = std::max(hi, double(p.x));
  }
  for (int id = 0; id <= 21; ++id) {
    const auto slot = trough.slotOf(id);
    ASSERT_TRUE(slot.has_value()) << id;
    const Eigen::Vector3d p = trough.slot(*slot);
    EXPECT_LT(std::abs(p.x()), s->geometry.length / 2.0) << id;
    EXPECT_GE(p.x() - r, lo) << id << ": inside the channel's head end";
    EXPECT_LE(p.x() + r, hi) << id << ": inside its foot end";
  }
}

}  // namespace
}  // namespace pool::render
