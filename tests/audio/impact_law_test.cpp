// The loudness law: zero under the floor, speed^exponent above it, flat past the cap.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "client/audio/impact_law.h"

namespace pool::audio {
namespace {

TEST(ImpactLaw, SilentUnderTheFloorAndForNonsense) {
  const ImpactLaw law{0.05, 8.0, 2.0, 0.01, 1.2};
  EXPECT_EQ(law.amplitude(0.049), 0.0);
  EXPECT_EQ(law.amplitude(0.0), 0.0);
  EXPECT_EQ(law.amplitude(-3.0), 0.0);
  EXPECT_EQ(law.amplitude(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_GT(law.amplitude(0.05), 0.0);
}

TEST(ImpactLaw, AmplitudeFollowsThePowerLawUpToTheCap) {
  const ImpactLaw law{0.05, 8.0, 2.0, 0.01, 1.2};
  EXPECT_DOUBLE_EQ(law.amplitude(2.0), 0.01);
  // Doubling the speed multiplies the amplitude by 2^1.2 ≈ 2.297.
  EXPECT_NEAR(law.amplitude(4.0) / law.amplitude(2.0), 2.2974, 1e-3);
  EXPECT_NEAR(law.amplitude(1.0) / law.amplitude(0.5), 2.2974, 1e-3);
  EXPECT_DOUBLE_EQ(law.amplitude(20.0), law.amplitude(8.0));
  EXPECT_DOUBLE_EQ(law.amplitude(std::numeric_limits<double>::infinity()), law.amplitude(8.0));
}

TEST(ImpactLaw, BrightnessRisesAsTheFifthRootAndIsBounded) {
  const ImpactLaw law{0.05, 8.0, 2.0, 0.01, 1.2};
  EXPECT_DOUBLE_EQ(law.brightness(2.0), 1.0);
  EXPECT_NEAR(law.brightness(4.0), std::pow(2.0, 0.2), 1e-12);
  EXPECT_DOUBLE_EQ(law.brightness(0.01), 0.7);
  EXPECT_LE(law.brightness(1e6), 1.4);
  EXPECT_LT(law.brightness(1.0), law.brightness(3.0));
}

TEST(ImpactLaws, EveryKindHasItsOwnLaw) {
  const ImpactLaws laws;
  EXPECT_EQ(&laws.of(SoundKind::CueStrike), &laws.strike);
  EXPECT_EQ(&laws.of(SoundKind::BallClick), &laws.click);
  EXPECT_EQ(&laws.of(SoundKind::CushionThump), &laws.thump);
  EXPECT_EQ(&laws.of(SoundKind::PocketDrop), &laws.pocket);
  EXPECT_GT(laws.pocket.amplitude(laws.pocket_fall_speed), 0.0);
  EXPECT_STREQ(toString(SoundKind::PocketDrop), "pocket_drop");
}

}  // namespace
}  // namespace pool::audio
