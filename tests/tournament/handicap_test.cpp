// Handicaps: the chance of a rack from two ratings (Glickman's expectation, with and without
// their deviations), the chance of a race (checked against every sequence of racks enumerated), and
// the racks on the wire that bring a race closest to even.
#include "server/tournament/handicap.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pool::tournament {
namespace {

// Expected values from enumerating every sequence of need + other_need - 1 racks and adding the
// probabilities of those in which the player reaches `need` (independent of the closed form).
constexpr double kTolerance = 1e-9;

TEST(HandicapTest, ARacksChanceIsTheRatingsExpectation) {
  EXPECT_NEAR(rackChance(1500, 1500), 0.5, kTolerance);
  // 1 / (1 + 10^(200/400)) and its complement.
  EXPECT_NEAR(rackChance(1500, 1700), 1.0 / (1.0 + std::sqrt(10.0)), kTolerance);
  EXPECT_NEAR(rackChance(1700, 1500) + rackChance(1500, 1700), 1.0, kTolerance);
  EXPECT_NEAR(rackChance(1500, 1900), 1.0 / 11.0, kTolerance);
}

TEST(HandicapTest, ARacesChanceAddsUpEveryWayToWinIt) {
  const double p = 1.0 / (1.0 + std::sqrt(10.0));
  EXPECT_NEAR(raceChance(p, 3, 3), 0.09350394731460844, kTolerance);
  EXPECT_NEAR(raceChance(p, 2, 3), 0.24538234617535526, kTolerance);
  EXPECT_NEAR(raceChance(p, 1, 3), 0.56146237949547, kTolerance);
  EXPECT_NEAR(raceChance(0.5, 3, 3), 0.5, kTolerance);
  EXPECT_NEAR(raceChance(0.6, 2, 4), 0.91296, kTolerance);
  EXPECT_EQ(raceChance(0.3, 0, 4), 1.0) << "nothing left to win";
  EXPECT_EQ(raceChance(0.3, 2, 0), 0.0) << "the other has won";
}

TEST(HandicapTest, TheSpotBringsTheRaceClosestToEven) {
  // 1500 v 1700, race to 3: 0.094, 0.245, 0.561 with 0, 1, 2 on the wire.
  // Certain ratings (no deviation) first.
  EXPECT_EQ(handicapSpots({1500}, {1700}, 3), (std::array<int, 2>{2, 0}));
  EXPECT_EQ(handicapSpots({1700}, {1500}, 3), (std::array<int, 2>{0, 2})) << "either seat";
  // 1500 v 1600, race to 5: 0.189, 0.315, 0.490, 0.699, 0.893.
  EXPECT_EQ(handicapSpots({1500}, {1600}, 5), (std::array<int, 2>{2, 0}));
  // 1500 v 1550, race to 7: 0.299, 0.413, 0.546, 0.686, ...
  EXPECT_EQ(handicapSpots({1550}, {1500}, 7), (std::array<int, 2>{0, 2}));
  // Nobody gets a spot when the ratings are equal, nor in a race to 1 (it would be the match).
  EXPECT_EQ(handicapSpots({1500}, {1500}, 9), (std::array<int, 2>{0, 0}));
  EXPECT_EQ(handicapSpots({1200}, {2000}, 1), (std::array<int, 2>{0, 0}));
  // However far apart, the spot stays below the race.
  EXPECT_EQ(handicapSpots({1000}, {2500}, 4), (std::array<int, 2>{3, 0}));
}

TEST(HandicapTest, UncertainRatingsPromiseLessAndGetSmallerSpots) {
  // A fresh key (1500, deviation 350) against an established 1700 (60): combined deviation
  // hypot(350, 60) = 355.1, g = 0.6637, a rack's chance 0.317753 (against 0.240253 when both are
  // certain); the race to 3 is won with 0, 1, 2 on the wire 0.187, 0.380, 0.682: 1 is nearest even
  // (2 when certain, above).
  EXPECT_NEAR(rackChance(1500, 1700, std::hypot(350.0, 60.0)), 0.317753, 1e-6);
  EXPECT_EQ(handicapSpots({1500, 350}, {1700, 60}, 3), (std::array<int, 2>{1, 0}));
  // Against 1900 (60): 0.043, 0.148, 0.445: 2.
  EXPECT_EQ(handicapSpots({1500, 350}, {1900, 60}, 3), (std::array<int, 2>{2, 0}));
  // 1500 v 1700 both at 200, race to 5: 0.096, 0.191, 0.348, 0.576, 0.830: 3.
  EXPECT_EQ(handicapSpots({1700, 200}, {1500, 200}, 5), (std::array<int, 2>{0, 3}));
}

}  // namespace
}  // namespace pool::tournament
