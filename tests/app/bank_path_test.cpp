// The bank aim aid against the mirror method worked out here: a path off the cushions is the
// straight line through the table's mirror images (unfolded), folded back onto the table; the
// cushion points are where that line crosses the images' edges (the cue ball's centre a radius
// inside the playing surface). Tolerance 1e-9 m.
#include "client/app/bank_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pool::app {
namespace {

const game::LoadedTable& caromTable() {
  static const game::LoadedTable table = [] {
    auto loaded = game::loadTable("carom-match");
    EXPECT_TRUE(loaded) << loaded.error();
    return *loaded;
  }();
  return table;
}

/// `u` on a line unfolded across mirror images of [-h, h], folded back into it.
double fold(double u, double h) {
  double m = std::fmod(u + h, 4 * h);
  if (m < 0) m += 4 * h;
  if (m > 2 * h) m = 4 * h - m;
  return m - h;
}

TEST(BankPath, ThreeCushionsFollowTheMirrorImages) {
  const auto& view = caromTable();
  const double r = view.radius();
  const double hx = view.halfLength() - r, hy = view.halfWidth() - r;
  const Eigen::Vector2d cue(-0.5, -0.2);
  const double yaw = 30.0 * std::numbers::pi / 180.0;
  const Eigen::Vector2d d(std::cos(yaw), std::sin(yaw));
  const std::vector<physics::Ball> alone{physics::restingBall(0, cue, r)};
  const BankPath path = bankPath(cue, yaw, alone, view, 0, 3, 0.2);
  // Where the unfolded line crosses x = hx (2k+1) and y = hy (2k+1) going up and right.
  std::vector<double> crossings;
  for (int k = 0; k < 4; ++k) {
    crossings.push_back((hx * (2 * k + 1) - cue.x()) / d.x());
    crossings.push_back((hy * (2 * k + 1) - cue.y()) / d.y());
  }
  std::sort(crossings.begin(), crossings.end());
  ASSERT_EQ(path.points.size(), 5u);  // the cue ball, three cushions, the end
  EXPECT_EQ(path.cushions, 3);
  EXPECT_FALSE(path.ball);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d unfolded = cue + crossings[static_cast<std::size_t>(k)] * d;
    EXPECT_NEAR(path.points[static_cast<std::size_t>(k) + 1].x(), fold(unfolded.x(), hx), 1e-9);
    EXPECT_NEAR(path.points[static_cast<std::size_t>(k) + 1].y(), fold(unfolded.y(), hy), 1e-9);
  }
  // The tail: 0.2 m on from the third cushion, short of the fourth.
  ASSERT_LT(crossings[2] + 0.2, crossings[3]);
  const Eigen::Vector2d end = cue + (crossings[2] + 0.2) * d;
  EXPECT_NEAR(path.points[4].x(), fold(end.x(), hx), 1e-9);
  EXPECT_NEAR(path.points[4].y(), fold(end.y(), hy), 1e-9);
}

TEST(BankPath, ABallOnTheWayEndsThePathWhereTheyTouch) {
  const auto& view = caromTable();
  const double r = view.radius();
  const double hy = view.halfWidth() - r;
  // Straight up the table's width from (0, 0) at 45°: the first cushion at (hy, hy); after it
  // the path heads down and right. A ball on that leg, 0.3 m on, is met 2r short of its centre.
  const Eigen::Vector2d cue(0.0, 0.0);
  const double yaw = std::numbers::pi / 4;
  const Eigen::Vector2d bounce(hy, hy);
  const Eigen::Vector2d leg = Eigen::Vector2d(1.0, -1.0).normalized();
  const Eigen::Vector2d red = bounce + 0.3 * leg;
  const std::vector<physics::Ball> balls{physics::restingBall(0, cue, r),
                                         physics::restingBall(2, red, r)};
  const BankPath path = bankPath(cue, yaw, balls, view, 0, 3, 0.2);
  ASSERT_TRUE(path.ball);
  EXPECT_EQ(*path.ball, 2);
  EXPECT_EQ(path.cushions, 1);
  ASSERT_EQ(path.points.size(), 3u);
  EXPECT_NEAR((path.points[1] - bounce).norm(), 0.0, 1e-9);
  EXPECT_NEAR((path.points[2] - (red - 2 * r * leg)).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace pool::app
