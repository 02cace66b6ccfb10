// The cue strike against Alciatore's closed forms (TP A-30 speed and spin, TP A-31 squirt).
#include <gtest/gtest.h>

#include "fixtures.h"
#include "physics/cue_strike.h"

namespace pool::physics::test {
namespace {

const table::PhysicsParams kParams{};

TEST(Strike, CentreHitSpeed) {
  CueShot shot;
  shot.speed = 2.0;
  auto s = strikeCueBall(shot, kParams);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->vel.norm(), 3.07694, 1e-5);  // 2·V0/(1 + m/M), published to 6 digits
  EXPECT_NEAR(s->ang_vel.norm(), 0.0, 1e-12);
}

TEST(Strike, HeightOffsetGivesSpinAboutRollAxis) {
  for (double b : {-0.5, -0.2, 0.2, 0.4, 0.5}) {
    CueShot shot;
    shot.speed = 2.0;
    shot.tip_height = b;
    auto s = strikeCueBall(shot, kParams);
    ASSERT_TRUE(s);
    const double v = s->vel.norm();
    // ω = 5 v b / (2R) about +y for a shot along +x.
    EXPECT_NEAR(s->ang_vel.y(), 5.0 * v * b / (2.0 * kParams.ball_radius), 1e-9);
    EXPECT_NEAR(s->ang_vel.x(), 0.0, 1e-12);
  }
  CueShot shot;
  shot.speed = 2.0;
  shot.tip_height = 0.5;
  EXPECT_NEAR(strikeCueBall(shot, kParams)->vel.norm(), 2.07793, 1e-5);
}

TEST(Strike, RightEnglishSpinsCounterClockwiseAndSquirtsLeft) {
  // docs/PHYSICS.md's example uses m_ball/m_end = 20 exactly (the default end mass gives 20.01).
  table::PhysicsParams params;
  params.cue_end_mass = params.ball_mass / 20.0;
  CueShot shot;
  shot.speed = 2.0;
  shot.tip_side = 0.2;
  auto s = strikeCueBall(shot, params);
  ASSERT_TRUE(s);
  EXPECT_GT(s->ang_vel.z(), 0.0);
  const double angle = std::atan2(s->vel.y(), s->vel.x()) / kDeg;
  EXPECT_NEAR(angle, 1.19936, 1e-4);  // TP A-31, m_ball/m_end = 20, a = 0.2
  shot.tip_side = -0.2;
  s = strikeCueBall(shot, params);
  EXPECT_NEAR(std::atan2(s->vel.y(), s->vel.x()) / kDeg, -1.19936, 1e-4);
}

TEST(Strike, BallSpeedModeHasNoSquirt) {
  CueShot shot;
  shot.speed = 1.5;
  shot.tip_side = 0.3;
  shot.speed_is_ball = true;
  auto s = strikeCueBall(shot, kParams);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->vel.x(), 1.5, 1e-12);
  EXPECT_NEAR(s->vel.y(), 0.0, 1e-12);
}

TEST(Strike, ElevatedCueDrivesBallDown) {
  CueShot shot;
  shot.speed = 3.0;
  shot.elevation = 45 * kDeg;
  auto s = strikeCueBall(shot, kParams);
  ASSERT_TRUE(s);
  EXPECT_LT(s->vel.z(), 0.0);
  EXPECT_NEAR(-s->vel.z(), s->vel.x(), 1e-9);
}

TEST(Strike, MiscueLimitIsLegalAndBeyondIsRejected) {
  CueShot shot;
  shot.speed = 2.0;
  shot.tip_side = 0.3;
  shot.tip_height = 0.4;  // exactly 0.5
  EXPECT_TRUE(strikeCueBall(shot, kParams));
  shot.tip_height = 0.41;
  auto s = strikeCueBall(shot, kParams);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("miscue"), std::string::npos);
}

TEST(Strike, NonFiniteAndOutOfRangeValuesAreRejected) {
  CueShot shot;
  shot.speed = std::nan("");
  EXPECT_EQ(validateShot(shot, kParams).error(), "speed: must be a finite number");
  EXPECT_EQ(validateShot(shot, kParams).code(), ShotProblem::NonFinite);
  shot.speed = 12.5;  // kMaxShotSpeed is 12
  EXPECT_EQ(validateShot(shot, kParams).error(), "speed: must be in (0, 12] m/s");
  shot.speed = 2.0;
  EXPECT_TRUE(validateShot(shot, kParams).ok());
  shot.elevation = 90 * kDeg;  // kMaxElevationDeg is 89
  EXPECT_EQ(validateShot(shot, kParams).error(), "elevation: must be in [0, 89] degrees");
  shot.elevation = 89 * kDeg;  // exactly the limit, converted from degrees
  EXPECT_TRUE(validateShot(shot, kParams).ok());
  shot.elevation = 0;
  shot.yaw = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validateShot(shot, kParams).error(), "yaw: must be a finite number");
  shot.yaw = 100.0;  // any heading: a turn more or less strikes the same way
  EXPECT_TRUE(validateShot(shot, kParams).ok());
}

}  // namespace
}  // namespace pool::physics::test
