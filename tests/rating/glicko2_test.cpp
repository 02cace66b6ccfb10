// Glicko-2 against Glickman's worked example ("Example of the Glicko-2 system", 2013, steps 1-8).
#include "server/rating/glicko2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pool::rating {
namespace {

// The example: a 1500 player (RD 200, volatility 0.06, τ = 0.5) beats a 1400 (RD 30), loses to a
// 1550 (RD 100) and to a 1700 (RD 300). Glickman gives r' = 1464.06, RD' = 151.52 and
// σ' = 0.05999, computed from intermediate values rounded to four decimals on the Glicko-2 scale
// (μ' = -0.2069, φ' = 0.8722): half a unit of that fourth decimal is 0.0087 on the Glicko scale,
// so r' and RD' are held to 0.015 (with the printed rounding); σ' to 1e-5 (printed cut to 5
// decimals).
TEST(Glicko2, GlickmansWorkedExample) {
  const Rating player{1500.0, 200.0, 0.06};
  const std::vector<GameResult> games = {
      {{1400.0, 30.0, 0.06}, 1.0}, {{1550.0, 100.0, 0.06}, 0.0}, {{1700.0, 300.0, 0.06}, 0.0}};
  const Rating after = updated(player, games, 0.5);
  EXPECT_NEAR(after.rating, 1464.06, 0.015);
  EXPECT_NEAR(after.deviation, 151.52, 0.015);
  EXPECT_NEAR(after.volatility, 0.05999, 1e-5);
}

// Without games only the deviation grows: φ' = sqrt(φ² + σ²) on the Glicko-2 scale (step 6).
TEST(Glicko2, APeriodWithoutGamesOnlyWidensTheDeviation) {
  const Rating player{1620.0, 80.0, 0.06};
  const Rating after = updated(player, {}, 0.5);
  const double phi = 80.0 / 173.7178;
  EXPECT_DOUBLE_EQ(after.rating, 1620.0);
  EXPECT_NEAR(after.deviation, 173.7178 * std::sqrt(phi * phi + 0.06 * 0.06), 1e-9);
  EXPECT_DOUBLE_EQ(after.volatility, 0.06);
}

// Two new players of equal standing: by symmetry the winner gains what the loser loses, and
// both become more certain.
TEST(Glicko2, EqualPlayersMoveByTheSameAmountEachWay) {
  const auto [winner, loser] = afterMatch(Rating{}, Rating{});
  EXPECT_GT(winner.rating, 1500.0);
  EXPECT_NEAR(winner.rating - 1500.0, 1500.0 - loser.rating, 1e-9);
  EXPECT_LT(winner.deviation, 350.0);
  EXPECT_NEAR(winner.deviation, loser.deviation, 1e-9);
}

// An upset moves ratings further than the expected result does.
TEST(Glicko2, AnUpsetCountsForMoreThanTheExpectedResult) {
  const Rating strong{1800.0, 60.0, 0.06};
  const Rating weak{1400.0, 60.0, 0.06};
  const auto [favourite_won, underdog_lost] = afterMatch(strong, weak);
  const auto [underdog_won, favourite_lost] = afterMatch(weak, strong);
  EXPECT_GT(underdog_won.rating - weak.rating, favourite_won.rating - strong.rating);
  EXPECT_GT(strong.rating - favourite_lost.rating, weak.rating - underdog_lost.rating);
}

}  // namespace
}  // namespace pool::rating
