// Ball in hand starts at the nearest legal spot.
#include "client/app/placement_search.h"

#include <gtest/gtest.h>

#include "app_fixture.h"
#include "rules/placement.h"

namespace pool::app::test {
namespace {

const rules::TableContext& nineFootContext() {
  return nineFoot().context;
}

TEST(PlacementSearchTest, AFreeSpotIsKept) {
  const auto& table = nineFootContext();
  const std::vector balls{physics::restingBall(5, {0.5, 0.2}, table.ball_radius)};
  const Eigen::Vector2d wanted(-0.2, 0.1);
  const auto at = nearestLegalPlacement(rules::BallInHand::Anywhere, wanted, balls, table);
  ASSERT_TRUE(at);
  EXPECT_EQ(*at, wanted);
}

TEST(PlacementSearchTest, ASpotOnABallMovesJustClearOfIt) {
  const auto& table = nineFootContext();
  const double r = table.ball_radius;
  const std::vector balls{physics::restingBall(5, {0.5, 0.2}, r)};
  const auto at = nearestLegalPlacement(rules::BallInHand::Anywhere, {0.5, 0.2}, balls, table);
  ASSERT_TRUE(at);
  EXPECT_TRUE(rules::checkCueBallPlacement(rules::BallInHand::Anywhere, *at, balls, table).ok());
  const double distance = (*at - Eigen::Vector2d(0.5, 0.2)).norm();
  EXPECT_GE(distance, 2 * r - 1e-6);  // touching is allowed (the rules give 1 µm)
  EXPECT_LT(distance, 2 * r + r);     // the grid's half-radius steps: within a radius of touching
}

TEST(PlacementSearchTest, BehindTheHeadStringItStaysBehindIt) {
  const auto& table = nineFootContext();
  const double head = table.spots.head_string_x;
  const std::vector<physics::Ball> balls;
  const auto at =
      nearestLegalPlacement(rules::BallInHand::BehindHeadString, {head + 0.1, 0.0}, balls, table);
  ASSERT_TRUE(at);
  EXPECT_LT(at->x(), head);
}

TEST(PlacementSearchTest, NoLegalSpotInReachIsEmpty) {
  const auto& table = nineFootContext();
  EXPECT_FALSE(nearestLegalPlacement(rules::BallInHand::None, {0.0, 0.0}, {}, table));
}

}  // namespace
}  // namespace pool::app::test
