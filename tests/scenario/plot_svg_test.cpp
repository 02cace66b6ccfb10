// The SVG plot: to scale, six pockets and the noses, a path per moving ball, events, byte-stable.
#include <gtest/gtest.h>

#include "bad_scenarios.h"
#include "scenario/ball_style.h"
#include "scenario/scenario.h"
#include "svg_check.h"

namespace pool::scenario {
namespace {

using testing::countOf;

Scenario twoBalls() {
  auto s = parseScenario(testing::goodScenario().dump());
  EXPECT_TRUE(s.hasValue()) << s.error();
  return *s;
}

// The cue ball rolls into the 1 at x = 0.3 (which goes on into a pocket); the 1 leaves a path.
physics::ShotOutcome madeUpOutcome(const Scenario& s) {
  physics::ShotOutcome o;
  for (int k = 0; k <= 10; ++k) {
    physics::Sample sample;
    sample.t = 0.1 * k;
    sample.balls = s.balls;
    sample.balls[0].pos.x() = -0.635 + 0.08 * k;
    if (k > 5) sample.balls[1].pos.x() = 0.3 + 0.1 * (k - 5);
    sample.balls[1].state = k > 8 ? physics::MotionState::Pocketed : physics::MotionState::Rolling;
    o.trajectory.push_back(sample);
  }
  o.balls = o.trajectory.back().balls;
  physics::Event hit;
  hit.t = 0.5;
  hit.type = physics::EventType::BallBall;
  hit.ball_b = 1;
  hit.pos = physics::Vec3(0.243, 0.0, 0.028575);
  physics::Event cushion = hit;
  cushion.type = physics::EventType::BallCushion;
  cushion.ball_a = 1;
  cushion.ball_b = -1;
  cushion.where = "foot";
  o.events = {hit, cushion};
  o.t_rest = 1.0;
  return o;
}

TEST(PlotSvg, IsAWellFormedPictureOfTheTable) {
  const Scenario s = twoBalls();
  const std::string svg = plotSvg(s, madeUpOutcome(s));
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(testing::tagBalance(svg), "");
  EXPECT_EQ(countOf(svg, "class=\"pocket\""), 6u);
  EXPECT_EQ(countOf(svg, "class=\"nose\""), s.geometry.noses.size());
  EXPECT_EQ(countOf(svg, "class=\"rail\""), 1u);
  EXPECT_EQ(countOf(svg, "class=\"cloth\""), 1u);
}

TEST(PlotSvg, IsToScale) {
  const Scenario s = twoBalls();
  const std::string svg = plotSvg(s, madeUpOutcome(s));
  // 1 m = 400 px: the cloth is 2.54 m x 1.27 m.
  EXPECT_NE(svg.find("class=\"cloth\""), std::string::npos);
  EXPECT_NE(svg.find("width=\"1016.00\" height=\"508.00\" class=\"cloth\""), std::string::npos);
  // Balls are circles of radius R.
  EXPECT_NE(svg.find("r=\"11.43\""), std::string::npos);
}

TEST(PlotSvg, OnePathPerMovingBallAndEventMarks) {
  const Scenario s = twoBalls();
  const std::string svg = plotSvg(s, madeUpOutcome(s));
  EXPECT_EQ(countOf(svg, "class=\"path\""), 2u);
  EXPECT_EQ(countOf(svg, "data-ball=\"0\""), 1u);
  EXPECT_EQ(countOf(svg, "class=\"event ball_ball\""), 2u);  // the two strokes of an x
  EXPECT_EQ(countOf(svg, "class=\"event ball_cushion\""), 1u);
}

TEST(PlotSvg, ABallThatDoesNotMoveHasNoPath) {
  const Scenario s = twoBalls();
  physics::ShotOutcome o = madeUpOutcome(s);
  for (auto& sample : o.trajectory) sample.balls[1] = s.balls[1];
  o.balls[1] = s.balls[1];
  const std::string svg = plotSvg(s, o);
  EXPECT_EQ(countOf(svg, "class=\"path\""), 1u);
}

TEST(PlotSvg, StripesAreDashedAndColoursFollowTheBalls) {
  auto s = parseScenario(testing::withRaw("/balls/1/id", "9"));
  ASSERT_TRUE(s.hasValue()) << s.error();
  const std::string svg = plotSvg(*s, madeUpOutcome(*s));
  EXPECT_NE(
      svg.find("data-ball=\"9\" fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\" "
               "stroke=\"#f2c200\" stroke-width=\"2\" stroke-dasharray"),
      std::string::npos);
}

TEST(PlotSvg, SameOutcomeSameBytes) {
  const Scenario s = twoBalls();
  EXPECT_EQ(plotSvg(s, madeUpOutcome(s)), plotSvg(s, madeUpOutcome(s)));
}

// A table's own set: the snooker black drawn black (a pool set would draw id 21 grey), the carom
// red (id 2, blue in a pool set) red.
TEST(PlotSvg, SnookerAndCaromTablesDrawTheirOwnBalls) {
  auto snooker = loadScenario("snooker_black");
  ASSERT_TRUE(snooker) << snooker.error();
  EXPECT_EQ(ballStyle(21, snooker->spec).colour, "#111111");
  EXPECT_EQ(ballStyle(7, snooker->spec).colour, ballStyle(1, snooker->spec).colour);  // reds
  const std::string svg = plotSvg(*snooker, runScenario(*snooker).value());
  EXPECT_NE(svg.find("data-ball=\"21\" fill=\"none\""), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"#111111\""), std::string::npos);
  EXPECT_EQ(svg.find("#888888"), std::string::npos);
  auto carom = loadScenario("three_cushion");
  ASSERT_TRUE(carom) << carom.error();
  EXPECT_EQ(ballStyle(2, carom->spec).colour, "#d42222");
  EXPECT_EQ(ballStyle(1, carom->spec).colour, "#f2c200");
  EXPECT_NE(ballStyle(2, carom->spec).colour, ballStyle(2).colour);
}

}  // namespace
}  // namespace pool::scenario
