// The aim line finds the first ball or cushion on the cue line, the call follows from it, and a
// click calls what the game lets it.
#include "client/app/aim_line.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app_fixture.h"
#include "rules/snooker.h"
#include "table/rack.h"

namespace pool::app::test {
namespace {

physics::Ball resting(int id, double x, double y) {
  return physics::restingBall(id, Eigen::Vector2d(x, y), nineFoot().radius());
}

// The heading from `cue` that sends the ball at `object` toward pocket `pocket` (ghost ball).
double aimAt(const Eigen::Vector2d& cue, const Eigen::Vector2d& object, int pocket) {
  const auto& view = nineFoot();
  const Eigen::Vector2d to = (view.pockets[pocket].mouth - object).normalized();
  const Eigen::Vector2d ghost = object - 2 * view.radius() * to;
  return std::atan2(ghost.y() - cue.y(), ghost.x() - cue.x());
}

// The pocket with the fullest cut from `cue` over the ball at `object`.
int easiestPocket(const Eigen::Vector2d& cue, const Eigen::Vector2d& object) {
  const auto& view = nineFoot();
  int best = 0;
  double best_dot = -2;
  for (int i = 0; i < static_cast<int>(view.pockets.size()); ++i) {
    const double d = (view.pockets[i].mouth - object).normalized().dot((object - cue).normalized());
    if (d > best_dot) {
      best_dot = d;
      best = i;
    }
  }
  return best;
}

TEST(AimLineTest, StraightAtABallStopsAtTwoRadii) {
  const double r = nineFoot().radius();
  const std::vector balls{resting(0, -0.5, 0.0), resting(4, 0.4, 0.0), resting(1, 0.6, 0.0)};
  const auto aim = predictAim(Eigen::Vector2d(-0.5, 0.0), 0.0, balls, nineFoot());
  ASSERT_TRUE(aim.ball);
  EXPECT_EQ(*aim.ball, 4);
  EXPECT_NEAR(aim.contact.x(), 0.4 - 2 * r, 1e-12);
  EXPECT_NEAR(aim.object_dir.x(), 1.0, 1e-12);
}

TEST(AimLineTest, ACutSendsTheBallTowardThePocketAimedAt) {
  const Eigen::Vector2d cue(0.3, -0.2), object(0.9, 0.35);
  const auto& view = nineFoot();
  for (int pocket = 0; pocket < static_cast<int>(view.pockets.size()); ++pocket) {
    const Eigen::Vector2d to = view.pockets[pocket].mouth - object;
    const Eigen::Vector2d from_cue = object - cue;
    if (to.normalized().dot(from_cue.normalized()) < 0.5) continue;  // too thin a cut
    const std::vector balls{resting(0, cue.x(), cue.y()), resting(11, object.x(), object.y())};
    const auto aim = predictAim(cue, aimAt(cue, object, pocket), balls, view);
    ASSERT_TRUE(aim.ball) << view.pockets[pocket].name;
    EXPECT_EQ(aim.pocket, pocket) << view.pockets[pocket].name;
    EXPECT_NEAR(aim.object_dir.dot(to.normalized()), 1.0, 1e-9);
  }
}

TEST(AimLineTest, NothingInTheWayMeansACushion) {
  const double r = nineFoot().radius();
  const std::vector balls{resting(0, 0.0, 0.0), resting(2, 0.5, 0.3)};
  const auto aim = predictAim(Eigen::Vector2d(0.0, 0.0), std::numbers::pi, balls, nineFoot());
  EXPECT_FALSE(aim.ball);
  EXPECT_NEAR(aim.contact.x(), -(nineFoot().halfLength() - r), 1e-12);
  EXPECT_NEAR(aim.contact.y(), 0.0, 1e-12);
}

TEST(AimLineTest, PocketedBallsAreNotInTheWay) {
  auto gone = resting(4, 0.4, 0.0);
  gone.state = physics::MotionState::Pocketed;
  const std::vector balls{resting(0, -0.5, 0.0), gone, resting(1, 0.6, 0.0)};
  const auto aim = predictAim(Eigen::Vector2d(-0.5, 0.0), 0.0, balls, nineFoot());
  ASSERT_TRUE(aim.ball);
  EXPECT_EQ(*aim.ball, 1);
}

TEST(AimLineTest, TheCallFollowsTheRules) {
  const Eigen::Vector2d cue(0.3, -0.2);
  const std::vector balls{resting(0, cue.x(), cue.y()), resting(11, 0.9, 0.35),
                          resting(8, -0.9, 0.35)};
  const auto at_eleven =
      predictAim(cue, aimAt(cue, {0.9, 0.35}, easiestPocket(cue, {0.9, 0.35})), balls, nineFoot());
  rules::GameState state;

  state.phase = rules::Phase::Break;
  EXPECT_EQ(autoCall(at_eleven, state, balls, nineFoot(), rules::Game::EightBall), ShotCall{});

  state.phase = rules::Phase::Open;
  const ShotCall call = autoCall(at_eleven, state, balls, nineFoot(), rules::Game::EightBall);
  EXPECT_EQ(call.ball, 11);
  EXPECT_EQ(call.pocket, nineFoot().pockets[at_eleven.pocket].name);
  EXPECT_FALSE(call.safety);

  // Solids: the 11 is not the shooter's to call, so the shot becomes a safety.
  state.phase = rules::Phase::Assigned;
  state.groups = {rules::Group::Solids, rules::Group::Stripes};
  state.shooter = 0;
  const ShotCall safe = autoCall(at_eleven, state, balls, nineFoot(), rules::Game::EightBall);
  EXPECT_TRUE(safe.safety);
  EXPECT_FALSE(safe.ball);

  // On the 8 (no solids left): aiming at it calls it, with the pocket it heads for.
  const int pocket = easiestPocket(cue, {-0.9, 0.35});
  const auto at_eight = predictAim(cue, aimAt(cue, {-0.9, 0.35}, pocket), balls, nineFoot());
  const ShotCall eight = autoCall(at_eight, state, balls, nineFoot(), rules::Game::EightBall);
  EXPECT_EQ(eight.ball, 8);
  EXPECT_EQ(eight.pocket, nineFoot().pockets[pocket].name);
}

// The WPA's rules: 9-ball calls no shot; in 10-ball every shot is called, and the lowest ball is
// hit first. The automatic call follows: none in 9-ball, the lowest ball when the aim meets it
// first in 10-ball, else a safety.
TEST(AimLineTest, RotationGamesCallByTheirOwnRules) {
  const Eigen::Vector2d cue(0.3, -0.2);
  const std::vector balls{resting(0, cue.x(), cue.y()), resting(7, 0.9, 0.35),
                          resting(4, -0.9, 0.35)};
  const auto at_seven =
      predictAim(cue, aimAt(cue, {0.9, 0.35}, easiestPocket(cue, {0.9, 0.35})), balls, nineFoot());
  const int pocket = easiestPocket(cue, {-0.9, 0.35});
  const auto at_four = predictAim(cue, aimAt(cue, {-0.9, 0.35}, pocket), balls, nineFoot());
  rules::GameState state;
  state.phase = rules::Phase::Open;
  EXPECT_EQ(autoCall(at_four, state, balls, nineFoot(), rules::Game::NineBall), ShotCall{});
  const ShotCall four = autoCall(at_four, state, balls, nineFoot(), rules::Game::TenBall);
  EXPECT_EQ(four.ball, 4);
  EXPECT_EQ(four.pocket, nineFoot().pockets[pocket].name);
  const ShotCall seven = autoCall(at_seven, state, balls, nineFoot(), rules::Game::TenBall);
  EXPECT_TRUE(seven.safety);
  EXPECT_FALSE(seven.ball);
  // In 8-ball with open groups the 7 is the shooter's to call.
  EXPECT_EQ(autoCall(at_seven, state, balls, nineFoot(), rules::Game::EightBall).ball, 7);
}

TEST(AimLineTest, AClickCallsAPocketInPoolAndNominatesOnlyWhatSnookerAllows) {
  // Pool: every object ball on the table but the one struck, every pocket, nothing nominated.
  physics::Ball gone = resting(5, 0.0, 0.0);
  gone.state = physics::MotionState::Pocketed;
  const std::vector<physics::Ball> pool{resting(0, -0.6, 0.0), resting(3, 0.3, 0.1), gone};
  const ClickTargets eight = clickTargetsFor(rules::Game::EightBall, pool, 0, nineFoot());
  ASSERT_EQ(eight.balls.size(), 1u);
  EXPECT_EQ(eight.balls[0].first, 3);
  EXPECT_EQ(eight.pockets.size(), nineFoot().pockets.size());
  EXPECT_FALSE(nominableFor(rules::Game::EightBall, rules::GameState{}, pool));

  // Snooker: no pocket; every ball may be clicked (a practice table drags them), but a ball is
  // nominated only as the rules allow (rules::checkSnookerIntent).
  const std::vector<physics::Ball> snooker{resting(0, -0.6, 0.0), resting(4, 0.3, 0.1),
                                           resting(table::kSnookerGreen, 0.5, -0.2),
                                           resting(table::kSnookerBlack, 0.8, 0.0)};
  const ClickTargets targets = clickTargetsFor(rules::Game::Snooker, snooker, 0, nineFoot());
  EXPECT_TRUE(targets.pockets.empty());
  EXPECT_EQ(targets.balls.size(), 3u);
  rules::GameState state = rules::newFrame(0);
  state.phase = rules::Phase::Open;
  EXPECT_EQ(nominableFor(rules::Game::Snooker, state, snooker), std::vector<int>{})
      << "on a red nothing is nominated";
  state.ball_on = rules::kOnColour;
  EXPECT_EQ(nominableFor(rules::Game::Snooker, state, snooker),
            (std::vector<int>{table::kSnookerGreen, table::kSnookerBlack}));
  state.ball_on = rules::kOnRed;
  state.free_ball = true;
  EXPECT_EQ(nominableFor(rules::Game::Snooker, state, snooker),
            (std::vector<int>{4, table::kSnookerGreen, table::kSnookerBlack}));
}

}  // namespace
}  // namespace pool::app::test
