// The shared scenes in assets/scenes: each loads, runs to rest, and does what its name says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scenario/scenario.h"
#include "table/rack.h"

namespace pool::scenario {
namespace {

using physics::EventType;

struct Ran {
  Scenario scenario;
  physics::ShotOutcome outcome;
};

Ran runScene(const std::string& name, double sample_hz = 0.0) {
  auto s = loadScenario(name);
  EXPECT_TRUE(s.hasValue()) << name << ": " << s.error();
  if (!s) return {};
  s->options.sample_hz = sample_hz;
  auto o = runScenario(*s);
  EXPECT_TRUE(o.hasValue()) << name << ": " << o.error();
  if (!o) return {*s, {}};
  return {*s, *o};
}

const physics::Ball& finalBall(const Ran& r, int id) {
  return *std::find_if(r.outcome.balls.begin(), r.outcome.balls.end(),
                       [id](const auto& b) { return b.id == id; });
}

std::vector<physics::Event> eventsOf(const Ran& r, EventType type, int ball) {
  std::vector<physics::Event> out;
  for (const auto& e : r.outcome.events) {
    if (e.type == type && (e.ball_a == ball || e.ball_b == ball)) out.push_back(e);
  }
  return out;
}

class EveryScene : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryScene, LoadsAndComesToRest) {
  const Ran r = runScene(GetParam());
  EXPECT_FALSE(r.outcome.truncated);
  ASSERT_TRUE(r.outcome.t_rest.has_value());
  ASSERT_FALSE(r.outcome.events.empty());
  EXPECT_EQ(r.outcome.events.front().type, EventType::Strike);
  EXPECT_EQ(r.outcome.balls.size(), r.scenario.balls.size());
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene,
                         ::testing::Values("break", "stun", "follow", "draw", "bank", "cut30",
                                           "jump", "masse", "rattle", "straight_pocket",
                                           "three_cushion", "snooker_black"));

TEST(Scenes, BreakHitsTheApexBallFirst) {
  const Ran r = runScene("break");
  ASSERT_EQ(r.scenario.balls.size(), 16u);
  EXPECT_DOUBLE_EQ(r.scenario.shot.speed, 8.0);
  const auto spots = table::spotsFor(r.scenario.spec);
  EXPECT_NEAR((r.scenario.balls[0].pos.head<2>() - spots.head_spot).norm(), 0.0, 1e-12);
  const auto hits = eventsOf(r, EventType::BallBall, 0);
  ASSERT_FALSE(hits.empty());
  const int apex = hits.front().ball_a == 0 ? hits.front().ball_b : hits.front().ball_a;
  const auto& apex_ball = r.scenario.balls[static_cast<std::size_t>(apex)];
  EXPECT_NEAR((apex_ball.pos.head<2>() - spots.foot_spot).norm(), 0.0, 1e-9);
}

// How far the cue ball ended past the point where it met the 1, along the shot's line (m).
double pastContact(const Ran& r) {
  const Eigen::Vector2d d(std::cos(r.scenario.shot.yaw), std::sin(r.scenario.shot.yaw));
  const Eigen::Vector2d contact =
      r.scenario.balls[1].pos.head<2>() - 2 * r.scenario.spec.params.ball_radius * d;
  return (finalBall(r, 0).pos.head<2>() - contact).dot(d);
}

TEST(Scenes, StunStopsTheCueBallNearTheContact) {
  const Ran r = runScene("stun");
  EXPECT_EQ(finalBall(r, 1).state, physics::MotionState::Pocketed);
  EXPECT_NEAR(pastContact(r), 0.0, 0.1);
}

TEST(Scenes, FollowGoesOn) {
  const Ran r = runScene("follow");
  EXPECT_EQ(finalBall(r, 1).state, physics::MotionState::Pocketed);
  EXPECT_TRUE(pastContact(r) > 0.3 || finalBall(r, 0).state == physics::MotionState::Pocketed);
}

TEST(Scenes, DrawComesBack) {
  const Ran r = runScene("draw");
  EXPECT_EQ(finalBall(r, 1).state, physics::MotionState::Pocketed);
  EXPECT_LT(pastContact(r), -0.3);
}

TEST(Scenes, BankOffTheRightCushionIntoTheLeftSidePocket) {
  const Ran r = runScene("bank");
  const auto cushions = eventsOf(r, EventType::BallCushion, 1);
  ASSERT_FALSE(cushions.empty());
  EXPECT_NE(cushions.front().where.find("right"), std::string::npos) << cushions.front().where;
  const auto pockets = eventsOf(r, EventType::Pocket, 1);
  ASSERT_EQ(pockets.size(), 1u);
  EXPECT_EQ(pockets.front().where, "left_side");
}

TEST(Scenes, JumpFliesOverTheBlocker) {
  const Ran r = runScene("jump");
  EXPECT_GE(r.scenario.shot.elevation, 30.0 * std::numbers::pi / 180.0);
  EXPECT_FALSE(eventsOf(r, EventType::Airborne, 0).empty());
  const auto hits = eventsOf(r, EventType::BallBall, 1);
  const auto land = eventsOf(r, EventType::Land, 0);
  ASSERT_FALSE(land.empty());
  // Whatever the cue ball does later, it does not touch the blocker on its way over.
  EXPECT_TRUE(hits.empty() || hits.front().t > land.front().t);
  EXPECT_TRUE(physics::onTable(finalBall(r, 0).state));
}

TEST(Scenes, MasseCurves) {
  const Ran r = runScene("masse", 200.0);
  const double y0 = r.scenario.balls[0].pos.y();
  double first_cushion = 1e9;
  for (const auto& e : eventsOf(r, EventType::BallCushion, 0))
    first_cushion = std::min(first_cushion, e.t);
  double largest = 0.0;
  for (const auto& sample : r.outcome.trajectory) {
    if (sample.t < first_cushion)
      largest = std::max(largest, std::abs(sample.balls[0].pos.y() - y0));
  }
  EXPECT_GT(largest, 0.02);
}

TEST(Scenes, RattleMeetsAJaw) {
  const Ran r = runScene("rattle");
  std::size_t jaws = 0;
  for (const auto& e : eventsOf(r, EventType::BallCushion, 1))
    jaws += e.where.rfind("jaw_", 0) == 0 ? 1 : 0;
  EXPECT_GE(jaws, 2u);
}

TEST(Scenes, StraightPocketPotsTheOne) {
  const Ran r = runScene("straight_pocket");
  const auto pockets = eventsOf(r, EventType::Pocket, 1);
  ASSERT_EQ(pockets.size(), 1u);
  EXPECT_EQ(pockets.front().where, "foot_right_corner");
  EXPECT_EQ(finalBall(r, 1).state, physics::MotionState::Pocketed);
}

// UMB, World Rules of Carom Billiard, three cushions: a point when the cue ball touches both
// object balls and at least three cushions before it touches the second. Counted here from the
// event log, independently of any rules code.
TEST(Scenes, ThreeCushionScoresAPoint) {
  const Ran r = runScene("three_cushion");
  EXPECT_EQ(r.scenario.spec.name, "carom-match");
  int first = -1, cushions_before_second = -1, cushions = 0;
  for (const auto& e : r.outcome.events) {
    if (e.type == EventType::BallCushion && e.ball_a == 0) ++cushions;
    if (e.type != EventType::BallBall || (e.ball_a != 0 && e.ball_b != 0)) continue;
    const int other = e.ball_a == 0 ? e.ball_b : e.ball_a;
    if (first < 0) {
      first = other;
    } else if (other != first && cushions_before_second < 0) {
      cushions_before_second = cushions;
    }
  }
  EXPECT_EQ(first, 2);  // the red first, as the opening requires
  ASSERT_GE(cushions_before_second, 0) << "the cue ball never reached the second object ball";
  EXPECT_GE(cushions_before_second, 3);
  // No ball can leave a table without pockets other than over a rail, and none did.
  for (const auto& b : r.outcome.balls) {
    EXPECT_EQ(b.state, physics::MotionState::Stationary) << b.id;
    // At rest on the slate: the centre one radius up, the carom ball's 30.75 mm.
    EXPECT_NEAR(b.pos.z(), 0.03075, 1e-9) << b.id;
  }
}

TEST(Scenes, SnookerBlackDropsInTheTopCorner) {
  const Ran r = runScene("snooker_black");
  const auto pockets = eventsOf(r, EventType::Pocket, 21);  // the black
  ASSERT_EQ(pockets.size(), 1u);
  EXPECT_EQ(pockets.front().where, "foot_left_corner");
  // The first contact is at two snooker radii (52.5 mm between centres), the cue ball's centre
  // one snooker radius above the slate.
  const auto hits = eventsOf(r, EventType::BallBall, 0);
  ASSERT_FALSE(hits.empty());
  EXPECT_NEAR(hits.front().pos.z(), 0.02625, 1e-9);
  const Eigen::Vector2d black(1.4605, 0.0);
  EXPECT_NEAR((hits.front().pos.head<2>() - black).norm(), 0.0525, 1e-6);
}

TEST(Scenes, SamplingChangesNoResult) {
  const Ran plain = runScene("break");
  const Ran sampled = runScene("break", 200.0);
  EXPECT_EQ(resultJson(plain.scenario, plain.outcome), resultJson(plain.scenario, sampled.outcome));
}

}  // namespace
}  // namespace pool::scenario
