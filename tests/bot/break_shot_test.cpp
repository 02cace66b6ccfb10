// The bot's break on hand racks: where it stands and aims, and how often it pots a ball when
// played with a strong player's execution noise.
#include <gtest/gtest.h>

#include <cmath>

#include "client/bot/ai/break_shot.h"
#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/shot_verifier.h"
#include "support/ai_fixture.h"
#include "table/rack.h"

namespace pool::bot::test {
namespace {

std::vector<physics::Ball> handRack(std::uint64_t seed) {
  std::vector<physics::Ball> balls{resting(0, 0.0, 0.0)};
  const auto& view = nineFoot();
  for (const auto& p : table::rackFor(table::RackType::EightBall, view.spec, view.radius(), seed,
                                      table::RackGenerator::Hand)) {
    balls.push_back(resting(p.id, p.pos.x(), p.pos.y()));
  }
  return balls;
}

TEST(BreakShotTest, EachSideMirrorsTheOtherBehindTheHeadString) {
  const auto& view = nineFoot();
  const Vec2 apex = view.context.spots.foot_spot;
  const BreakStroke plan{0.4, 0.3, 11.0, -0.1};
  const PlannedShot left = breakShot(view, apex, plan, 1);
  const PlannedShot right = breakShot(view, apex, plan, -1);
  ASSERT_TRUE(left.cue_ball_at && right.cue_ball_at);
  EXPECT_LT(left.cue_ball_at->x(), view.headStringX());
  EXPECT_DOUBLE_EQ(left.cue_ball_at->y(), 0.4);
  EXPECT_DOUBLE_EQ(right.cue_ball_at->y(), -0.4);
  // Mirrored across the long string: the headings are opposite (1e-12 rad of rounding).
  EXPECT_NEAR(left.cue.yaw, -right.cue.yaw, 1e-12);
  // The aim passes 0.3 R from the apex ball's centre, on the cue ball's side of it.
  const Vec2 heading(std::cos(left.cue.yaw), std::sin(left.cue.yaw));
  const Vec2 to = apex - *left.cue_ball_at;
  const double miss = heading.x() * to.y() - heading.y() * to.x();  // signed distance, m
  EXPECT_NEAR(std::abs(miss), 0.3 * view.radius(), 1e-6);
  const Vec2 aim_point = *left.cue_ball_at + heading * to.dot(heading);
  EXPECT_GT(aim_point.y(), apex.y());
  EXPECT_DOUBLE_EQ(left.cue.speed, 11.0);
  EXPECT_DOUBLE_EQ(left.cue.tip_height, -0.1);
}

// A pro breaks and pots a ball more often than not (issue's target: 60 % of racks at the
// professional level, the olympiad noise). 40 racks of their own seeds (never those the breaks
// were measured on), each break planned, then played once with the noise. A centred 9 m/s break
// on the same racks, the bot's before, is the floor it must clear.
TEST(BreakShotTest, UnderTheOlympiadNoiseTheBreakPotsABallInMostRacks) {
  const auto& view = nineFoot();
  ShotVerifier verifier(view);
  ShotPlanner planner(view);
  const ExecutionNoise noise = olympiadNoise(view.radius());
  constexpr int kRacks = 40;
  Rng rng(3), baseline_rng(3);
  int pots = 0, baseline_pots = 0;
  for (int k = 0; k < kRacks; ++k) {
    auto balls = handRack(7000 + static_cast<std::uint64_t>(k));
    const PlannedShot shot = planner.plan(balls, rules::newRack(0));
    ASSERT_EQ(shot.kind, ShotKind::Break);
    ASSERT_TRUE(shot.cue_ball_at);
    auto played = balls;
    played[0] = resting(0, shot.cue_ball_at->x(), shot.cue_ball_at->y());
    PlannedShot noisy = shot;
    noisy.cue = perturbed(shot.cue, noise, rng);
    const Trial trial = verifier.run(played, rules::newRack(0), noisy);
    ASSERT_TRUE(trial.judged) << trial.error;
    if (!trial.verdict.pocketed.empty()) ++pots;

    const PlannedShot centred =
        breakShot(view, apexBall(view, balls), BreakStroke{0.0, 0.0, 9.0, -0.1}, 1);
    auto from_centre = balls;
    from_centre[0] = resting(0, centred.cue_ball_at->x(), centred.cue_ball_at->y());
    PlannedShot noisy_centre = centred;
    noisy_centre.cue = perturbed(centred.cue, noise, baseline_rng);
    const Trial baseline = verifier.run(from_centre, rules::newRack(0), noisy_centre);
    if (!baseline.verdict.pocketed.empty()) ++baseline_pots;
  }
  EXPECT_GE(pots, kRacks * 6 / 10) << pots << " of " << kRacks << " breaks potted a ball";
  EXPECT_GT(pots, baseline_pots) << "no better than a centred 9 m/s break (" << baseline_pots
                                 << ")";
}

// A practice table's "ask the bot" on a fresh rack advised "safety at 2.00 m/s": a racked table
// is now told apart, frozen or hand-racked, 8- and 9-ball, and a broken one is not.
TEST(BreakShotTest, ARackedTableIsToldFromABrokenOne) {
  const auto& view = nineFoot();
  for (auto generator : {table::RackGenerator::Frozen, table::RackGenerator::Hand}) {
    for (auto type : {table::RackType::EightBall, table::RackType::NineBall}) {
      std::vector<physics::Ball> balls{resting(0, -0.7, 0.0)};
      for (const auto& p : table::rackFor(type, view.spec, view.radius(), 9, generator)) {
        balls.push_back(resting(p.id, p.pos.x(), p.pos.y()));
      }
      EXPECT_TRUE(looksRacked(view, balls));
      balls.back().pos.x() = view.context.spots.foot_spot.x() - 0.1;  // out in front of the apex
      EXPECT_FALSE(looksRacked(view, balls));
    }
  }
  // A planner asked with the break's state from a racked practice table plays a break.
  std::vector<physics::Ball> balls = handRack(4);
  ASSERT_TRUE(looksRacked(view, balls));
  ShotPlanner planner(view);
  EXPECT_EQ(planner.plan(balls, rules::newRack(0)).kind, ShotKind::Break);
}

}  // namespace
}  // namespace pool::bot::test
