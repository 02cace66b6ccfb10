// A practice table's drag: the layout it sends keeps every ball and brings back a lost cue ball
// (every drag was refused with "the cue ball must be on the table" after a scratch); its rack
// keys rack the games of its table.
#include "client/app/practice_layout.h"

#include <gtest/gtest.h>

#include "app_fixture.h"
#include "rules/placement.h"
#include "table/rack.h"

namespace pool::app::test {
namespace {

physics::Ball at(int id, double x, double y) {
  return physics::restingBall(id, Eigen::Vector2d(x, y), kRadius);
}

const protocol::BallSpot* spotOf(const std::vector<protocol::BallSpot>& layout, int id) {
  for (const auto& s : layout) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

TEST(PracticeLayoutTest, TheDraggedBallMovesAndTheOthersStay) {
  const auto& table = nineFoot().context;
  const std::vector<physics::Ball> balls{at(0, -0.6, 0.0), at(3, 0.2, 0.1), at(9, 0.5, -0.3)};
  const auto layout = layoutWithMove(balls, 3, {0.3, 0.2}, table);
  ASSERT_EQ(layout.size(), 3u);
  EXPECT_DOUBLE_EQ(spotOf(layout, 3)->x, 0.3);
  EXPECT_DOUBLE_EQ(spotOf(layout, 3)->y, 0.2);
  EXPECT_DOUBLE_EQ(spotOf(layout, 0)->x, -0.6);
  EXPECT_DOUBLE_EQ(spotOf(layout, 9)->y, -0.3);
}

TEST(PracticeLayoutTest, ACueBallThatLeftTheTableComesBackToTheHeadSpot) {
  const auto& table = nineFoot().context;
  physics::Ball lost = at(0, 0.0, 0.0);
  lost.state = physics::MotionState::Pocketed;
  std::vector<physics::Ball> balls{lost, at(3, 0.2, 0.1), at(9, 0.5, -0.3)};
  auto layout = layoutWithMove(balls, 3, {0.3, 0.2}, table);
  const auto* cue = spotOf(layout, physics::kCueBall);
  ASSERT_TRUE(cue) << "a layout without the cue ball is refused";
  EXPECT_DOUBLE_EQ(cue->x, table.spots.head_spot.x());
  EXPECT_DOUBLE_EQ(cue->y, table.spots.head_spot.y());
  // With a ball on the head spot, the cue ball goes to the nearest point the rules accept.
  balls.push_back(at(5, table.spots.head_spot.x(), table.spots.head_spot.y()));
  layout = layoutWithMove(balls, 3, {0.3, 0.2}, table);
  cue = spotOf(layout, physics::kCueBall);
  ASSERT_TRUE(cue);
  const Eigen::Vector2d p(cue->x, cue->y);
  EXPECT_GE((p - table.spots.head_spot).norm(), 2 * kRadius);
  std::vector<physics::Ball> others{at(3, 0.3, 0.2), at(9, 0.5, -0.3), balls.back()};
  EXPECT_TRUE(rules::checkCueBallPlacement(rules::BallInHand::Anywhere, p, others, table).ok());
}

TEST(PracticeLayoutTest, TheRackKeysRackTheGamesOfTheTable) {
  // A pool table: the key's own game. Snooker's and the carom table: their game, whichever key
  // (the server refuses another table's game).
  for (const int asked : {8, 9, 10}) {
    EXPECT_EQ(practiceRack(rules::Game::NineBall, asked), asked);
    EXPECT_EQ(practiceRack(rules::Game::Snooker, asked), 22);
    EXPECT_EQ(practiceRack(rules::Game::ThreeCushion, asked), 3);
  }
}

TEST(PracticeLayoutTest, ASnookerDragKeepsAllTwentyTwoBalls) {
  auto loaded = game::loadTable("snooker-12ft");
  ASSERT_TRUE(loaded) << loaded.error();
  const auto& table = loaded->context;
  std::vector<physics::Ball> balls;
  for (const auto& p : table::snookerRack(loaded->spec, table.ball_radius)) {
    balls.push_back(physics::restingBall(p.id, p.pos, table.ball_radius));
  }
  const auto layout = layoutWithMove(balls, 21, {1.2, 0.5}, table);
  ASSERT_EQ(layout.size(), 22u);
  EXPECT_EQ(spotOf(layout, 21)->x, 1.2);
  EXPECT_EQ(spotOf(layout, 20)->x, balls[20].pos.x());
  protocol::PracticeRequest command;
  command.action = protocol::PracticeAction::Layout;
  command.balls = layout;
  EXPECT_TRUE(
      protocol::checkPracticeFields(command, loaded->spec.length / 2, loaded->spec.width / 2).ok());
}

}  // namespace
}  // namespace pool::app::test
