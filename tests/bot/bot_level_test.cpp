// The bot's levels: their names, their noise (the olympiad's at pro, more at each level below),
// and a planner that judges its pots under its own noise takes the one it makes more often.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "client/bot/ai/bot_level.h"
#include "client/bot/ai/shot_planner.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

constexpr Level kLevels[] = {Level::Beginner, Level::Club, Level::League, Level::Pro};

TEST(BotLevel, EveryLevelIsNamedAndNothingElseIsOne) {
  for (Level level : kLevels) EXPECT_EQ(levelFromString(toString(level)), level);
  EXPECT_EQ(levelNames(), (std::vector<std::string>{"beginner", "club", "league", "pro"}));
  EXPECT_EQ(levelFromString("expert"), std::nullopt);
  EXPECT_EQ(levelFromString("Pro"), std::nullopt);
  EXPECT_EQ(levelFromString(""), std::nullopt);
  EXPECT_EQ(kDefaultLevel, Level::Club);
}

TEST(BotLevel, ProPlaysUnderTheOlympiadNoiseAndEachLevelBelowStraysMore) {
  const double r = nineFoot().radius();
  // Greenspan et al., "The 2008 computational pool tournament" (ICGA J. 31(4)): sigma 0.125 deg
  // on the aim, 0.1 deg on the elevation, 0.075 m/s on the speed, 0.5 mm on each tip offset.
  const double deg = std::numbers::pi / 180.0;
  const ExecutionNoise pro = levelNoise(Level::Pro, r);
  EXPECT_NEAR(pro.yaw, 0.125 * deg, 1e-15);
  EXPECT_NEAR(pro.elevation, 0.1 * deg, 1e-15);
  EXPECT_NEAR(pro.speed, 0.075, 1e-15);
  EXPECT_NEAR(pro.tip * r, 0.5e-3, 1e-15);
  for (std::size_t i = 1; i < std::size(kLevels); ++i) {
    const ExecutionNoise lower = levelNoise(kLevels[i - 1], r), upper = levelNoise(kLevels[i], r);
    EXPECT_GT(lower.yaw, upper.yaw) << toString(kLevels[i - 1]);
    EXPECT_GT(lower.elevation, upper.elevation);
    EXPECT_GT(lower.speed, upper.speed);
    EXPECT_GT(lower.tip, upper.tip);
    EXPECT_LE(plannerOptionsFor(kLevels[i - 1], r).samples,
              plannerOptionsFor(kLevels[i], r).samples);
  }
}

// The cue ball 0.1 m behind a solid that lies straight in line with a corner pocket 1.4 m
// away, and a solid 0.3 m from a side pocket's mouth that needs a cut of `cut` (rad) into it.
std::vector<physics::Ball> straightAndCut(bool with_straight, bool with_cut, double cut,
                                          double straight_at = 1.4, double cue_at = 1.5,
                                          double cut_at = 0.3) {
  const auto& view = nineFoot();
  const Vec2 cue = onPocketLine("foot_left_corner", Vec2(-0.2, 0.1), cue_at);
  const Vec2 straight = onPocketLine("foot_left_corner", cue, straight_at);
  // The cut ball: on a line from the side pocket's mouth into the table, where the cue ball's path
  // to the ghost ball makes `cut` with the pot line.
  const auto& side = view.pockets[static_cast<std::size_t>(pocketIndex(view, "right_side"))];
  const double r = view.radius();
  Vec2 object = side.mouth;
  double best = 1e9;
  for (double angle = -1.2; angle <= 1.2; angle += 0.002) {
    const Vec2 into = side.mouth.y() > 0 ? Vec2(std::sin(angle), -std::cos(angle))
                                         : Vec2(std::sin(angle), std::cos(angle));
    const Vec2 o = side.mouth + into * cut_at;
    const Vec2 ghost = o + into * 2 * r;
    const Vec2 path = (ghost - cue).normalized();
    const double made = std::acos(std::clamp(path.dot(-into), -1.0, 1.0));
    if (std::abs(made - cut) < best) {
      best = std::abs(made - cut);
      object = o;
    }
  }
  std::vector<physics::Ball> on{resting(0, cue.x(), cue.y()), resting(8, 0.9, -0.45),
                                resting(9, -0.9, -0.5)};
  if (with_straight) on.push_back(resting(1, straight.x(), straight.y()));
  if (with_cut) on.push_back(resting(2, object.x(), object.y()));
  std::vector<physics::Ball> balls;
  for (int id = 0; id < 16; ++id) balls.push_back(pocketed(id));
  for (const auto& b : on) balls[static_cast<std::size_t>(b.id)] = b;
  return balls;
}

TEST(BotLevel, SamplingItsNoiseTheBotTakesThePotItMakesMoreOften) {
  const auto& view = nineFoot();
  // Position weighed at nothing: the pots compare by the chance of making them alone.
  PlannerOptions club = plannerOptionsFor(Level::Club, view.radius());
  club.leave_weight = 0.0;
  ASSERT_GT(club.samples, 0);
  const double cut = 0.9;  // rad, about 52 degrees
  ShotPlanner straight_only(view, club), cut_only(view, club), both(view, club);
  const PlannedShot a = straight_only.plan(straightAndCut(true, false, cut), solidsToShoot());
  const PlannedShot b = cut_only.plan(straightAndCut(false, true, cut), solidsToShoot());
  const PlannedShot c = both.plan(straightAndCut(true, true, cut), solidsToShoot());
  PlannerOptions exact_options;
  exact_options.leave_weight = 0.0;
  ShotPlanner exact(view, exact_options);
  const PlannedShot d = exact.plan(straightAndCut(true, true, cut), solidsToShoot());
  // Each alone: an aim error moves the cue ball by e = d sigma at the contact (d its travel to
  // it) and turns the object ball by e / (2R cos cut). With the cue ball 4 cm from contact the
  // straight pot is made nearly every time at the club's noise (sigma 0.44 deg: the object ball
  // about 1 cm off at the pocket); the cut, a longer approach at 52 degrees, far less often. The
  // club samples each shortlisted pot 8 times: shares in eighths.
  ASSERT_EQ(a.kind, ShotKind::Pot) << describe(a);
  ASSERT_EQ(b.kind, ShotKind::Pot) << describe(b);
  ASSERT_TRUE(a.success && b.success);
  EXPECT_GE(*a.success, 7.0 / 8) << describe(a);
  EXPECT_LE(*b.success, 5.0 / 8) << describe(b);
  // Together: the club calls the straight one. Judged by one exact trial each (a flawless
  // player's view, the easier-looking line first: the cut is 0.3 m from its pocket) it takes the
  // cut, so the choice is the sampling's.
  EXPECT_EQ(c.called_ball, 1) << describe(c);
  EXPECT_EQ(c.called_pocket, "foot_left_corner");
  EXPECT_EQ(d.called_ball, 2) << describe(d);
}

}  // namespace
}  // namespace pool::bot::test
