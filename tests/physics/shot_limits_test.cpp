// checkShotRange at and just past each limit (docs/SIM-CONTRACT.md: 12 m/s, 89°, the miscue).
#include "physics/shot_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace pool::physics {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

ShotValues good() {
  return {2.0, 5 * kDeg, 0.1, -0.2, 1.0};
}

// Speed in (0, 12] m/s, elevation in [0°, 89°], tip offset within the miscue limit (0.5 R), |yaw|
// at most a turn: exactly a limit is legal (within kRangeTolerance, 1e-12), past it by 1e-9 is not.
TEST(ShotRange, EachLimitHoldsExactlyAndRefusesJustPastIt) {
  EXPECT_TRUE(checkShotRange(good()));
  struct Case {
    const char* name;
    void (*set)(ShotValues&, double);
    double at, past;
    ShotProblem problem;
  };
  const Case cases[] = {
      {"speed", [](ShotValues& v, double x) { v.speed = x; }, 12.0, 12.0 + 1e-9,
       ShotProblem::SpeedOutOfRange},
      {"elevation", [](ShotValues& v, double x) { v.elevation = x; }, 89 * kDeg, 89 * kDeg + 1e-9,
       ShotProblem::ElevationOutOfRange},
      {"tip", [](ShotValues& v, double x) { v.tip_side = x, v.tip_height = 0.0; }, 0.5, 0.5 + 1e-9,
       ShotProblem::TipOutOfRange},
      {"yaw", [](ShotValues& v, double x) { v.yaw = x; }, -2 * std::numbers::pi,
       -2 * std::numbers::pi - 1e-9, ShotProblem::YawOutOfRange},
  };
  for (const Case& c : cases) {
    ShotValues v = good();
    c.set(v, c.at);
    EXPECT_TRUE(checkShotRange(v)) << c.name << ": " << checkShotRange(v).error();
    c.set(v, c.past);
    const auto refused = checkShotRange(v);
    EXPECT_EQ(refused.code(), c.problem) << c.name;
    EXPECT_EQ(refused.error().rfind(c.name, 0), 0u) << c.name << ": " << refused.error();
  }
}

TEST(ShotRange, ZeroSpeedAndNegativeElevationAreRefused) {
  ShotValues v = good();
  v.speed = 0.0;
  EXPECT_EQ(checkShotRange(v).error(), "speed: must be in (0, 12] m/s");
  v = good();
  v.elevation = -1e-6;
  EXPECT_EQ(checkShotRange(v).error(), "elevation: must be in [0, 89] degrees");
}

TEST(ShotRange, ANonFiniteValueIsRefusedBeforeAnyRange) {
  ShotValues v = good();
  v.tip_height = std::numeric_limits<double>::quiet_NaN();
  v.speed = 50.0;
  EXPECT_EQ(checkShotRange(v).code(), ShotProblem::NonFinite);
  EXPECT_EQ(checkShotRange(v).error(), "tip_height: must be a finite number");
}

TEST(ShotRange, AnAimHasNoSpeedToCheck) {
  ShotValues v = good();
  v.speed = 0.0;
  EXPECT_TRUE(checkShotRange(v, {}, false));
  v.elevation = 90 * kDeg;
  EXPECT_EQ(checkShotRange(v, {}, false).code(), ShotProblem::ElevationOutOfRange);
}

TEST(ShotRange, ATableCanNarrowTheRanges) {
  ShotRanges narrow;
  narrow.max_speed = 4.0;
  narrow.miscue_limit = 0.25;
  ShotValues v = good();
  v.speed = 4.5;
  EXPECT_EQ(checkShotRange(v, narrow).error(), "speed: must be in (0, 4] m/s");
  v = good();
  v.tip_side = 0.3;
  v.tip_height = 0.0;
  EXPECT_EQ(checkShotRange(v, narrow).code(), ShotProblem::TipOutOfRange);
}

}  // namespace
}  // namespace pool::physics
