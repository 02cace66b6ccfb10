// Cue-ball placement before a shot: on the slate, not overlapping, behind the head string when
// required.
#include <gtest/gtest.h>

#include "rules/fixture.h"
#include "rules/placement.h"

namespace pool::rules {
namespace {

using test::ballAt;

std::vector<physics::Ball> table() {
  return {ballAt(0, 0.0, 0.0), ballAt(5, 0.5, 0.0), ballAt(9, -0.9, 0.2)};
}

TEST(Placement, AnywhereOnTheSlate) {
  auto ctx = test::nineFoot();
  EXPECT_TRUE(checkCueBallPlacement(BallInHand::Anywhere, {0.9, -0.4}, table(), ctx).ok());
  // Its own entry does not count as an overlap.
  EXPECT_TRUE(checkCueBallPlacement(BallInHand::Anywhere, {0.01, 0.0}, table(), ctx).ok());
  // Touching another ball is fine; overlapping is not.
  EXPECT_TRUE(
      checkCueBallPlacement(BallInHand::Anywhere, {0.5 - 2 * test::kR, 0.0}, table(), ctx).ok());
  auto overlap = checkCueBallPlacement(BallInHand::Anywhere, {0.5 - test::kR, 0.0}, table(), ctx);
  EXPECT_EQ(overlap.code(), PlacementProblem::Overlaps);
  EXPECT_EQ(overlap.error(), "the ball would overlap ball 5");
}

TEST(Placement, OffTheSlateIsRefused) {
  auto ctx = test::nineFoot();
  EXPECT_EQ(checkCueBallPlacement(BallInHand::Anywhere, {1.27, 0.0}, table(), ctx).code(),
            PlacementProblem::OffSlate);
  EXPECT_EQ(
      checkCueBallPlacement(BallInHand::Anywhere, {0.0, 0.635 - test::kR / 2}, table(), ctx).code(),
      PlacementProblem::OffSlate);
  EXPECT_EQ(checkCueBallPlacement(BallInHand::Anywhere, {std::nan(""), 0.0}, table(), ctx).code(),
            PlacementProblem::NotFinite);
}

TEST(Placement, OverAPocketHoleIsRefused) {
  auto ctx = test::nineFoot();
  ctx.holes.push_back({"foot_left_corner", {1.27, 0.635}, 0.07});
  EXPECT_EQ(
      checkCueBallPlacement(BallInHand::Anywhere, {1.27 - test::kR, 0.635 - test::kR}, table(), ctx)
          .code(),
      PlacementProblem::OverPocket);
}

TEST(Placement, BehindTheHeadString) {
  auto ctx = test::nineFoot();
  double hs = ctx.spots.head_string_x;
  EXPECT_TRUE(
      checkCueBallPlacement(BallInHand::BehindHeadString, {hs - 0.01, 0.0}, table(), ctx).ok());
  EXPECT_EQ(checkCueBallPlacement(BallInHand::BehindHeadString, {hs, 0.0}, table(), ctx).code(),
            PlacementProblem::NotBehindHeadString);
  EXPECT_EQ(checkCueBallPlacement(BallInHand::BehindHeadString, {0.2, 0.0}, table(), ctx).code(),
            PlacementProblem::NotBehindHeadString);
  // A ball behind the string is still an obstacle.
  EXPECT_EQ(checkCueBallPlacement(BallInHand::BehindHeadString, {-0.9, 0.2}, table(), ctx).code(),
            PlacementProblem::Overlaps);
}

TEST(Placement, WithoutBallInHandNothingMayBePlaced) {
  auto ctx = test::nineFoot();
  auto placed = placeCueBall(BallInHand::None, {-0.9, -0.3}, table(), ctx);
  EXPECT_FALSE(placed);
  EXPECT_NE(placed.error().find("in hand"), std::string::npos);
  EXPECT_STREQ(toString(PlacementProblem::NoBallInHand), "no_ball_in_hand");
  EXPECT_TRUE(placeCueBall(BallInHand::Anywhere, {-0.9, -0.3}, table(), ctx));
}

}  // namespace
}  // namespace pool::rules
