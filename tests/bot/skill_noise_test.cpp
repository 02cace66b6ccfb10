// Skill noise: none at skill 1, bounded by three sigmas, and fixed by the seed.
#include <gtest/gtest.h>

#include <cmath>

#include "client/bot/ai/skill_noise.h"

namespace pool::bot::test {
namespace {

physics::CueShot aShot() {
  physics::CueShot shot;
  shot.yaw = 0.7;
  shot.speed = 3.0;
  shot.speed_is_ball = true;
  return shot;
}

TEST(SkillNoiseTest, SkillOneAddsNothing) {
  SkillNoise noise(1.0, 42);
  for (int i = 0; i < 100; ++i) {
    const auto out = noise.apply(aShot());
    EXPECT_EQ(out.yaw, aShot().yaw);
    EXPECT_EQ(out.speed, aShot().speed);
  }
}

TEST(SkillNoiseTest, ErrorsAreBoundedAndScaleWithSkill) {
  SkillNoise noise(0.8, 7);
  EXPECT_NEAR(noise.yawSigma(), 0.2 * kYawSigmaAtZero, 1e-12);
  double sum_sq = 0.0;
  constexpr int kDraws = 4000;
  for (int i = 0; i < kDraws; ++i) {
    const auto out = noise.apply(aShot());
    const double yaw_error = out.yaw - aShot().yaw;
    EXPECT_LE(std::abs(yaw_error), 3 * noise.yawSigma() + 1e-15);
    EXPECT_LE(std::abs(out.speed / aShot().speed - 1), 3 * noise.speedSigma() + 1e-12);
    sum_sq += yaw_error * yaw_error;
  }
  // The spread is the advertised sigma (within sampling error).
  EXPECT_NEAR(std::sqrt(sum_sq / kDraws), noise.yawSigma(), 0.1 * noise.yawSigma());
}

TEST(SkillNoiseTest, TheSeedFixesTheSequence) {
  SkillNoise a(0.5, 123), b(0.5, 123), c(0.5, 124);
  bool differs = false;
  for (int i = 0; i < 50; ++i) {
    const auto x = a.apply(aShot()), y = b.apply(aShot()), z = c.apply(aShot());
    EXPECT_EQ(x.yaw, y.yaw);
    EXPECT_EQ(x.speed, y.speed);
    differs = differs || x.yaw != z.yaw;
  }
  EXPECT_TRUE(differs);
}

TEST(SkillNoiseTest, SpeedNeverExceedsTheLimit) {
  SkillNoise noise(0.0, 9);
  auto shot = aShot();
  shot.speed = 11.9;
  for (int i = 0; i < 500; ++i) EXPECT_LE(noise.apply(shot, 12.0).speed, 12.0);
}

}  // namespace
}  // namespace pool::bot::test
