// The cue's placement: its tip on the physics' struck point, its line along the strike direction,
// drawn back with the power, raised clear of the rails and of balls behind the cue ball.
#include "client/render/cue_pose.h"

#include <gtest/gtest.h>

#include <cmath>

#include "client/render/cue_profile.h"

namespace pool::render {
namespace {

constexpr float kR = 0.028575f;
constexpr float kDeg = 3.14159265f / 180.0f;

/// A 9-ft table's playing surface and rails, no balls.
CueObstacles table() {
  return {1.27f, 0.635f, 0.15f, 0.0413f, kR, {}};
}

TEST(CuePoseTest, TipOnTheStruckPointAlongThePhysicsLineWhenNothingBlocks) {
  const CueAim aim{{-0.6f, 0.1f, kR}, 0.3f, 0.2f, -0.3f, 5 * kDeg, 0.0f};
  const CuePlacement cue = placeCue(aim, table());
  // The strike frame written out: d, right, up; contact R (a right + b up − √(1 − a² − b²) d).
  const glm::vec3 d(std::cos(5 * kDeg) * std::cos(0.3f), std::cos(5 * kDeg) * std::sin(0.3f),
                    -std::sin(5 * kDeg));
  const glm::vec3 right(std::sin(0.3f), -std::cos(0.3f), 0.0f);
  const glm::vec3 up = glm::cross(right, d);
  const glm::vec3 struck =
      aim.cue_ball + kR * (0.2f * right - 0.3f * up - std::sqrt(1.0f - 0.04f - 0.09f) * d);
  EXPECT_LT(glm::length(cue.tip - struck), 1e-5f);
  EXPECT_LT(glm::length(cue.forward - d), 1e-5f);
  EXPECT_NEAR(cue.drawn_elevation, 5 * kDeg, 1e-6f);
  EXPECT_NEAR(glm::length(cue.butt - cue.tip), cueLength(), 1e-4);
  // The struck point is on the ball's surface.
  EXPECT_NEAR(glm::length(struck - aim.cue_ball), kR, 1e-6f);
}

TEST(CuePoseTest, PowerDrawsTheTipBackAlongTheLine) {
  const CueAim rest{{-0.6f, 0.0f, kR}, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  CueAim drawn = rest;
  drawn.power = 0.5f;
  const CuePlacement a = placeCue(rest, table());
  const CuePlacement b = placeCue(drawn, table());
  EXPECT_NEAR(glm::length(a.tip - b.tip), 0.5f * kMaxDrawBack, 1e-5f);
  EXPECT_NEAR(glm::dot(a.tip - b.tip, a.forward), 0.5f * kMaxDrawBack, 1e-5f);
}

/// Lowest clearance of the cue's surface over the rail band (negative: it passes through).
float railClearance(const CuePlacement& cue, const CueObstacles& o) {
  float lowest = 1.0f;
  for (float s = 0.0f; s <= cueLength(); s += 0.005f) {
    const glm::vec3 p = cue.tip - cue.forward * s;
    const bool over = std::abs(p.x) > o.half_length || std::abs(p.y) > o.half_width;
    const bool on_table =
        std::abs(p.x) < o.half_length + o.rail_outer && std::abs(p.y) < o.half_width + o.rail_outer;
    if (over && on_table) {
      lowest = std::min(lowest, p.z - float(cueRadiusAt(s)) - o.rail_top);
    }
  }
  return lowest;
}

TEST(CuePoseTest, NearACushionTheCueRisesOverTheRail) {
  const CueObstacles o = table();
  const CueAim aim{{-1.15f, 0.3f, kR}, 10 * kDeg, 0.0f, -0.3f, 0.0f, 0.5f};
  // Level, the cue would run through the cushion and rail behind the ball.
  CuePlacement level;
  level.forward = cueDirection(aim.yaw, 0.0f);
  level.tip = struckPoint(aim, kR) - level.forward * 0.5f * kMaxDrawBack;
  EXPECT_LT(railClearance(level, o), 0.0f);
  const CuePlacement cue = placeCue(aim, o);
  EXPECT_GT(cue.drawn_elevation, 1 * kDeg);
  EXPECT_GE(railClearance(cue, o), 0.0f);
  // Only the drawing rises: the tip stays on the line through the struck point.
  const glm::vec3 back = struckPoint(aim, kR) - cue.tip;
  EXPECT_NEAR(glm::length(glm::cross(back, cue.forward)), 0.0f, 1e-5f);
}

TEST(CuePoseTest, ABallBehindTheCueBallLiftsTheCueOverIt) {
  CueObstacles o = table();
  const glm::vec3 cue_ball(0.0f, 0.0f, kR);
  o.balls.push_back({-0.1f, 0.0f, kR});  // right behind, on the cue's line
  const CuePlacement cue = placeCue({cue_ball, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}, o);
  EXPECT_GT(cue.drawn_elevation, 10 * kDeg);
  for (float s = 0.0f; s <= cueLength(); s += 0.005f) {
    const glm::vec3 p = cue.tip - cue.forward * s;
    EXPECT_GE(glm::length(p - o.balls[0]), kR + float(cueRadiusAt(s))) << "s " << s;
  }
}

TEST(CuePoseTest, CueFadesOnlyWhenTheEyeIsAtItsAxis) {
  const CuePlacement cue = placeCue({{0.0f, 0.0f, kR}, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}, table());
  EXPECT_FLOAT_EQ(cueOpacity(cue, cue.tip - cue.forward * 0.7f + glm::vec3(0, 0, 0.2f)), 1.0f);
  EXPECT_LT(cueOpacity(cue, cue.tip - cue.forward * 0.7f + glm::vec3(0, 0, 0.02f)), 0.5f);
}

TEST(CuePoseTest, TheStrokeGoesThroughTheBallThenEnds) {
  EXPECT_FLOAT_EQ(strokePower(0.8f, 0.0f), 0.8f);  // from where it was drawn back
  // Forward all the way, accelerating: less than half the way in the first half of the time.
  EXPECT_GT(strokePower(0.8f, kStrokeForward * 0.5f), 0.8f - 0.5f * (0.8f - kFollowThrough));
  EXPECT_FLOAT_EQ(strokePower(0.8f, kStrokeForward), kFollowThrough);
  EXPECT_FLOAT_EQ(strokePower(0.8f, kStrokeEnd - 0.01f), kFollowThrough);
  EXPECT_TRUE(std::isnan(strokePower(0.8f, kStrokeEnd + 0.01f)));
  // Pushed through, the tip is past the struck point along the line.
  const CueAim aim{{0.0f, 0.0f, kR}, 0.0f, 0.0f, 0.0f, 0.0f, kFollowThrough};
  const CuePlacement cue = placeCue(aim, table());
  EXPECT_NEAR(glm::dot(cue.tip - struckPoint(aim, kR), cue.forward), -kFollowThrough * kMaxDrawBack,
              1e-5f);
}

}  // namespace
}  // namespace pool::render
