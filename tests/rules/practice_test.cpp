// The practice rule set: one player, no fouls, re-rack and re-place balls on demand.
#include <gtest/gtest.h>

#include <set>

#include "rules/fixture.h"
#include "rules/practice.h"
#include "table/rack.h"

namespace pool::rules {
namespace {

using test::LogBuilder;
using test::makeShot;

TEST(Practice, NoFoulsAndTheSamePlayerShoots) {
  auto balls = test::spreadLayout({1, 8, 12});
  // Hits the 8 first, no cushion, then scratches: nothing but the cue ball in hand.
  auto v =
      judgePractice(makeShot(balls, Intent::none(),
                             LogBuilder().hit(0, 8).pocket(8, "left_side").pocket(0, "right_side")),
                    test::nineFoot());
  ASSERT_TRUE(v) << v.error();
  EXPECT_TRUE(v->legal());
  EXPECT_FALSE(v->game_over);
  EXPECT_TRUE(v->turn_continues);
  EXPECT_EQ(v->next_shooter, 0);
  EXPECT_EQ(v->pocketed, std::vector<int>{8});
  EXPECT_EQ(v->ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(v->next.shooter, 0);
}

TEST(Practice, AMissIsJustAMiss) {
  auto balls = test::spreadLayout({1, 8, 12});
  auto v = judgePractice(makeShot(balls, Intent::none(), LogBuilder().hit(0, 1).rest(1).rest(0)),
                         test::nineFoot());
  ASSERT_TRUE(v);
  EXPECT_TRUE(v->fouls.empty());
  EXPECT_EQ(v->ball_in_hand, BallInHand::None);
}

TEST(Practice, ReRackOnDemand) {
  auto balls = practiceRack(test::nineFoot(), 7);
  ASSERT_EQ(balls.size(), 16u);
  std::set<int> ids;
  for (const auto& b : balls) ids.insert(b.id);
  EXPECT_EQ(ids.size(), 16u);
  EXPECT_EQ(balls[0].id, 0);
  EXPECT_TRUE(balls[0].pos.head<2>().isApprox(test::nineFoot().spots.head_spot));
}

TEST(Practice, RePlaceBallsOnDemand) {
  auto ctx = test::nineFoot();
  auto balls = test::withPocketed(test::spreadLayout({1, 8, 12}), {12});
  auto placed = placeBalls(balls, {{12, {0.0, 0.3}}, {0, {-0.5, 0.0}}}, ctx, Game::EightBall);
  ASSERT_TRUE(placed) << placed.error();
  for (const auto& b : *placed) {
    if (b.id == 12) {
      EXPECT_EQ(b.state, physics::MotionState::Stationary);
      EXPECT_DOUBLE_EQ(b.pos.y(), 0.3);
      EXPECT_DOUBLE_EQ(b.pos.z(), test::kR);
    }
  }
  auto clash = placeBalls(balls, {{12, {0.0, 0.3}}, {1, {0.0, 0.31}}}, ctx, Game::EightBall);
  ASSERT_FALSE(clash);
  EXPECT_EQ(clash.error(), "ball 1: the ball would overlap ball 12");
  const auto sixteen = placeBalls(balls, {{16, {0.0, 0.0}}}, ctx, Game::NineBall);
  ASSERT_FALSE(sixteen);
  EXPECT_EQ(sixteen.error(), "ball 16: not a ball id (0-15)");
  EXPECT_FALSE(placeBalls(balls, {{3, {2.0, 0.0}}}, ctx, Game::EightBall));
}

TEST(Practice, ATablesBallsAreItsGamesSet) {
  // A pool set 0-15, a snooker set 0-21 (the black, table::kSnookerBlack), three-cushion's
  // white, yellow and red 0-2.
  EXPECT_EQ(practiceMaxBallId(Game::EightBall), 15);
  EXPECT_EQ(practiceMaxBallId(Game::NineBall), 15);
  EXPECT_EQ(practiceMaxBallId(Game::TenBall), 15);
  EXPECT_EQ(practiceMaxBallId(Game::Snooker), table::kSnookerBlack);
  EXPECT_EQ(practiceMaxBallId(Game::ThreeCushion), kCaromRed);

  auto snooker = table::loadTableSpec("snooker-12ft");
  ASSERT_TRUE(snooker) << snooker.error();
  const TableContext table = tableContext(*snooker);
  // The black on its spot, beyond a pool table's end; one more ball is no snooker ball.
  const Eigen::Vector2d black = *table::snookerSpotOf(*snooker, table::kSnookerBlack);
  const auto placed = placeBalls({}, {{table::kSnookerBlack, black}}, table, Game::Snooker);
  ASSERT_TRUE(placed) << placed.error();
  ASSERT_EQ(placed->size(), 1u);
  EXPECT_EQ(placed->front().pos.head<2>(), black);
  const auto extra = placeBalls({}, {{22, {0.0, 0.0}}}, table, Game::Snooker);
  ASSERT_FALSE(extra);
  EXPECT_EQ(extra.error(), "ball 22: not a ball id (0-21)");
  // A snooker colour is no ball of a pool table.
  EXPECT_EQ(placeBalls({}, {{16, {0.0, 0.0}}}, test::nineFoot(), Game::EightBall).error(),
            "ball 16: not a ball id (0-15)");

  auto carom = table::loadTableSpec("carom-match");
  ASSERT_TRUE(carom) << carom.error();
  const TableContext carom_table = tableContext(*carom);
  EXPECT_TRUE(placeBalls({}, {{kCaromRed, {0.5, 0.0}}}, carom_table, Game::ThreeCushion));
  const auto fourth = placeBalls({}, {{3, {0.0, 0.0}}}, carom_table, Game::ThreeCushion);
  ASSERT_FALSE(fourth);
  EXPECT_EQ(fourth.error(), "ball 3: not a ball id (0-2)");
}

}  // namespace
}  // namespace pool::rules
