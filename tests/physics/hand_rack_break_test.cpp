// The same centred break on hand racks (table::rackFor, RackGenerator::Hand): a frozen triangle
// spreads mirror-symmetrically every time, racks with gaps of a few tenths of a millimetre never
// break the same way twice.
#include <gtest/gtest.h>

#include <vector>

#include "fixtures.h"

namespace pool::physics::test {
namespace {

/// The largest distance from a ball at rest on the table to the nearest ball of `b` mirrored
/// across the long string (y → −y), m; balls off the table count by their number only.
double mirrorMismatch(const std::vector<Ball>& balls) {
  double worst = 0.0;
  for (const Ball& a : balls) {
    if (!onTable(a.state)) continue;
    double nearest = 1e9;
    for (const Ball& b : balls) {
      if (!onTable(b.state)) continue;
      const Vec2 mirrored(b.pos.x(), -b.pos.y());
      nearest = std::min(nearest, (a.pos.head<2>() - mirrored).norm());
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

/// The largest distance between the same ball in two outcomes, m (a ball on the table in one and
/// not the other counts as 1 m).
double largestDifference(const std::vector<Ball>& a, const std::vector<Ball>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (onTable(a[i].state) != onTable(b[i].state)) return 1.0;
    if (onTable(a[i].state)) worst = std::max(worst, (a[i].pos - b[i].pos).norm());
  }
  return worst;
}

// A centred 8 m/s break (the fixture's breakShot) from the head spot. Tolerance: a frozen rack
// is symmetric to the rounding of its simulation, 1 mm here; "another break" means some ball
// ends at least 5 cm (about two ball widths) from where it ended on another rack.
TEST(HandRackBreak, AFrozenRackSpreadsSymmetricallyAndHandRacksNeverRepeat) {
  const auto frozen = shootReal(breakBalls(), breakShot());
  ASSERT_TRUE(frozen.t_rest);
  EXPECT_LT(mirrorMismatch(frozen.balls), 1e-3) << "the frozen rack broke asymmetrically";

  constexpr int kRacks = 6;
  std::vector<std::vector<Ball>> ends;
  for (int seed = 1; seed <= kRacks; ++seed) {
    const auto o = shootReal(breakBalls(table::RackGenerator::Hand, seed), breakShot());
    ASSERT_TRUE(o.t_rest) << "seed " << seed;
    EXPECT_GT(mirrorMismatch(o.balls), 0.05) << "seed " << seed << " spread symmetrically";
    ends.push_back(o.balls);
  }
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (std::size_t k = i + 1; k < ends.size(); ++k) {
      EXPECT_GT(largestDifference(ends[i], ends[k]), 0.05)
          << "seeds " << i + 1 << " and " << k + 1 << " broke alike";
    }
  }
}

}  // namespace
}  // namespace pool::physics::test
