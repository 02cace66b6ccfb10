// Racks and spots: 8-, 9- and 10-ball layouts, hand racks, seeds, and re-spotting on the long
// string.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "table/rack.h"

namespace pool::table {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kR = 0.028575;

TableSpec nineFoot() {
  auto s = loadTableSpec("wpa-9ft");
  EXPECT_TRUE(s) << s.error();
  return *s;
}

const BallPlacement& ball(const std::vector<BallPlacement>& rack, int id) {
  for (const BallPlacement& b : rack) {
    if (b.id == id) return b;
  }
  throw std::runtime_error("no ball " + std::to_string(id));
}

void expectNoOverlap(const std::vector<BallPlacement>& rack) {
  for (std::size_t i = 0; i < rack.size(); ++i) {
    for (std::size_t k = i + 1; k < rack.size(); ++k) {
      EXPECT_GE((rack[i].pos - rack[k].pos).norm(), 2.0 * kR - 1e-12)
          << rack[i].id << " and " << rack[k].id;
    }
  }
}

/// The ball nearest to a point.
int idAt(const std::vector<BallPlacement>& rack, const Vec2& p) {
  return std::min_element(rack.begin(), rack.end(),
                          [&](const BallPlacement& a, const BallPlacement& b) {
                            return (a.pos - p).norm() < (b.pos - p).norm();
                          })
      ->id;
}

TEST(Spots, QuarterLengthsFromTheCushions) {
  const TableSpec s = nineFoot();
  const Spots spots = spotsFor(s);
  EXPECT_DOUBLE_EQ(spots.foot_spot.x(), 0.635);
  EXPECT_DOUBLE_EQ(spots.foot_spot.y(), 0.0);
  EXPECT_DOUBLE_EQ(spots.head_spot.x(), -0.635);
  EXPECT_DOUBLE_EQ(spots.head_string_x, -0.635);
  EXPECT_EQ(spots.centre_spot, Vec2(0.0, 0.0));
  EXPECT_EQ(rackTypeFromString("8ball"), RackType::EightBall);
  EXPECT_EQ(rackTypeFromString("9ball"), RackType::NineBall);
  EXPECT_EQ(rackTypeFromString("10ball"), RackType::TenBall);
  EXPECT_FALSE(rackTypeFromString("11ball").has_value());
}

TEST(EightBallRack, LayoutFollowsTheRules) {
  const TableSpec s = nineFoot();
  const double gap = 0.0;  // a tight rack: neighbours frozen together
  const double pitch = 2.0 * kR + gap;
  const double row = pitch * std::sqrt(3.0) / 2.0;
  const Vec2 foot = spotsFor(s).foot_spot;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const auto rack = rackBalls(RackType::EightBall, s, kR, seed);
    ASSERT_EQ(rack.size(), 15u);
    std::set<int> ids;
    for (const BallPlacement& b : rack) ids.insert(b.id);
    ASSERT_EQ(ids, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}));
    expectNoOverlap(rack);
    EXPECT_TRUE(std::any_of(rack.begin(), rack.end(), [&](const BallPlacement& b) {
      return b.pos == foot;
    })) << "apex exactly on the foot spot";
    EXPECT_LT((ball(rack, 8).pos - (foot + Vec2(2.0 * row, 0.0))).norm(), 1e-12);
    const int left = idAt(rack, foot + Vec2(4.0 * row, 2.0 * pitch));
    const int right = idAt(rack, foot + Vec2(4.0 * row, -2.0 * pitch));
    const bool left_solid = left >= 1 && left <= 7;
    const bool right_solid = right >= 1 && right <= 7;
    EXPECT_NE(left_solid, right_solid) << "seed " << seed;
    EXPECT_NE(left, 8);
    EXPECT_NE(right, 8);
    for (const BallPlacement& b : rack)
      EXPECT_GE(b.pos.x(), foot.x());  // rows toward the foot cushion
  }
}

TEST(EightBallRack, NeighboursAreGapApart) {
  const TableSpec s = nineFoot();
  const double gap = 1e-4;
  const auto rack = rackBalls(RackType::EightBall, s, kR, 3, gap);
  int touching = 0;
  for (std::size_t i = 0; i < rack.size(); ++i) {
    for (std::size_t k = i + 1; k < rack.size(); ++k) {
      if (std::abs((rack[i].pos - rack[k].pos).norm() - (2.0 * kR + gap)) < 1e-12) ++touching;
    }
  }
  EXPECT_EQ(touching, 30);  // the edges of a 5-row triangular lattice
}

TEST(EightBallRack, SeedsAreDeterministicAndMatter) {
  const TableSpec s = nineFoot();
  const auto order = [&](std::uint64_t seed) {
    std::vector<int> ids;
    for (const BallPlacement& b : rackBalls(RackType::EightBall, s, kR, seed)) ids.push_back(b.id);
    return ids;
  };
  EXPECT_EQ(order(42), order(42));
  std::set<std::vector<int>> distinct;
  std::set<bool> solid_left;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    distinct.insert(order(seed));
    solid_left.insert(order(seed).back() <= 7);
  }
  EXPECT_GT(distinct.size(), 45u);
  EXPECT_EQ(solid_left.size(), 2u);  // both sides get the solid sometimes
}

TEST(EightBallRack, PinnedLayoutForSeedZero) {
  // The shuffle is our own PRNG, so this holds on every platform. Slot order: row by row from the
  // apex, each row from −y to +y.
  const auto rack = rackBalls(RackType::EightBall, nineFoot(), kR, 0);
  std::vector<int> ids;
  for (const BallPlacement& b : rack) ids.push_back(b.id);
  const std::vector<int> expected{5, 14, 13, 12, 8, 9, 4, 3, 15, 7, 2, 1, 10, 6, 11};
  EXPECT_EQ(ids, expected);
}

TEST(NineBallRack, DiamondWithOneAtTheApexAndNineInTheCentre) {
  const TableSpec s = nineFoot();
  const Vec2 foot = spotsFor(s).foot_spot;
  const double row = 2.0 * kR * std::sqrt(3.0) / 2.0;  // a tight rack
  std::set<std::vector<int>> distinct;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const auto rack = rackBalls(RackType::NineBall, s, kR, seed);
    ASSERT_EQ(rack.size(), 9u);
    std::set<int> ids;
    std::vector<int> order;
    for (const BallPlacement& b : rack) {
      ids.insert(b.id);
      order.push_back(b.id);
    }
    distinct.insert(order);
    EXPECT_EQ(ids, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    expectNoOverlap(rack);
    EXPECT_EQ(ball(rack, 1).pos, foot);
    EXPECT_LT((ball(rack, 9).pos - (foot + Vec2(2.0 * row, 0.0))).norm(), 1e-12);
    std::map<long, int> per_row;
    for (const BallPlacement& b : rack) ++per_row[std::lround((b.pos.x() - foot.x()) / row)];
    EXPECT_EQ(per_row, (std::map<long, int>{{0, 1}, {1, 2}, {2, 3}, {3, 2}, {4, 1}}));
  }
  EXPECT_GT(distinct.size(), 30u);
}

TEST(TenBallRack, TriangleWithOneAtTheApexAndTenInTheThirdRow) {
  const TableSpec s = nineFoot();
  const Vec2 foot = spotsFor(s).foot_spot;
  const double row = 2.0 * kR * std::sqrt(3.0) / 2.0;  // a tight rack
  std::set<std::vector<int>> distinct;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const auto rack = rackBalls(RackType::TenBall, s, kR, seed);
    ASSERT_EQ(rack.size(), 10u);
    std::set<int> ids;
    std::vector<int> order;
    for (const BallPlacement& b : rack) {
      ids.insert(b.id);
      order.push_back(b.id);
    }
    distinct.insert(order);
    EXPECT_EQ(ids, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    expectNoOverlap(rack);
    EXPECT_EQ(ball(rack, 1).pos, foot);
    EXPECT_LT((ball(rack, 10).pos - (foot + Vec2(2.0 * row, 0.0))).norm(), 1e-12);
    std::map<long, int> per_row;
    for (const BallPlacement& b : rack) ++per_row[std::lround((b.pos.x() - foot.x()) / row)];
    EXPECT_EQ(per_row, (std::map<long, int>{{0, 1}, {1, 2}, {2, 3}, {3, 4}}));
  }
  EXPECT_GT(distinct.size(), 30u);
}

TEST(Respot, FootSpotWhenFree) {
  const TableSpec s = nineFoot();
  EXPECT_EQ(respotPosition(s, kR, {}), spotsFor(s).foot_spot);
  EXPECT_EQ(respotPosition(s, kR, {Vec2(0.0, 0.3)}), spotsFor(s).foot_spot);
}

TEST(Respot, BehindTheBlockingBallThenInFront) {
  const TableSpec s = nineFoot();
  const Vec2 foot = spotsFor(s).foot_spot;
  const Vec2 blocker = foot + Vec2(0.01, 0.02);
  const Vec2 p = respotPosition(s, kR, {blocker});
  EXPECT_EQ(p.y(), 0.0);
  EXPECT_GT(p.x(), blocker.x());
  EXPECT_GE((p - blocker).norm(), 2.0 * kR);
  EXPECT_LT((p - blocker).norm(), 2.0 * kR + 1e-3);  // as near as possible

  // Fill the long string from the foot spot to the foot cushion: the ball goes in front.
  std::vector<Vec2> row;
  for (double x = foot.x(); x < s.length / 2.0; x += 2.0 * kR + 1e-4) row.push_back({x, 0.0});
  const Vec2 q = respotPosition(s, kR, row);
  EXPECT_LT(q.x(), foot.x());
  EXPECT_EQ(q.y(), 0.0);
  for (const Vec2& c : row) EXPECT_GE((q - c).norm(), 2.0 * kR);
  EXPECT_LT(foot.x() - q.x(), 2.0 * kR + 1e-3);
}

// A hand rack (rack.h, kRackStray: the WPA's ±0.005 in on a ball's diameter). Tolerance 1e-12 m
// on distances (the positions' rounding).
TEST(HandRack, EachBallWithinItsStrayOfItsSlotAndNoneOverlapping) {
  const TableSpec spec = nineFoot();
  constexpr double kEps = 1e-12;
  for (RackType type : {RackType::EightBall, RackType::NineBall, RackType::TenBall}) {
    double smallest_gap = 1.0, largest_gap = 0.0;
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
      const auto hand = rackFor(type, spec, kR, seed, RackGenerator::Hand);
      const auto slots = rackBalls(type, spec, kR, seed, 2.0 * kRackStray);
      const auto frozen = rackBalls(type, spec, kR, seed);
      ASSERT_EQ(hand.size(), slots.size());
      for (std::size_t i = 0; i < hand.size(); ++i) {
        EXPECT_EQ(hand[i].id, frozen[i].id) << "the seed orders the balls as a frozen rack";
        EXPECT_LE((hand[i].pos - slots[i].pos).norm(), kRackStray + kEps) << hand[i].id;
      }
      expectNoOverlap(hand);
      // Neighbours: slots one pitch apart. Their gap lies in [0, 4 kRackStray].
      const double pitch = 2.0 * kR + 2.0 * kRackStray;
      for (std::size_t i = 0; i < hand.size(); ++i) {
        for (std::size_t k = i + 1; k < hand.size(); ++k) {
          if (std::abs((slots[i].pos - slots[k].pos).norm() - pitch) > 1e-9) continue;
          const double gap = (hand[i].pos - hand[k].pos).norm() - 2.0 * kR;
          EXPECT_GE(gap, -kEps);
          EXPECT_LE(gap, 4.0 * kRackStray + kEps);
          smallest_gap = std::min(smallest_gap, gap);
          largest_gap = std::max(largest_gap, gap);
        }
      }
    }
    // Over 200 racks the gaps fill most of their range: from nearly touching to nearly 0.5 mm.
    EXPECT_LT(smallest_gap, 0.5 * kRackStray);
    EXPECT_GT(largest_gap, 3.0 * kRackStray);
  }
}

TEST(HandRack, TheSeedFixesItAndNoTwoSeedsRackAlike) {
  const TableSpec spec = nineFoot();
  const auto a = rackFor(RackType::NineBall, spec, kR, 42, RackGenerator::Hand);
  const auto again = rackFor(RackType::NineBall, spec, kR, 42, RackGenerator::Hand);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, again[i].id);
    EXPECT_EQ(a[i].pos.x(), again[i].pos.x());  // bit for bit
    EXPECT_EQ(a[i].pos.y(), again[i].pos.y());
  }
  std::set<std::pair<double, double>> apexes;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const auto r = rackFor(RackType::NineBall, spec, kR, seed, RackGenerator::Hand);
    apexes.insert({r[0].pos.x(), r[0].pos.y()});
  }
  EXPECT_EQ(apexes.size(), 50u);
}

TEST(HandRack, AFrozenGeneratorIsTheRackStoredMatchesHad) {
  const TableSpec spec = nineFoot();
  for (std::uint64_t seed : {0ULL, 7ULL, 123456789ULL}) {
    const auto old = rackBalls(RackType::EightBall, spec, kR, seed);
    const auto frozen = rackFor(RackType::EightBall, spec, kR, seed, RackGenerator::Frozen);
    ASSERT_EQ(old.size(), frozen.size());
    for (std::size_t i = 0; i < old.size(); ++i) {
      EXPECT_EQ(old[i].id, frozen[i].id);
      EXPECT_EQ(old[i].pos, frozen[i].pos);
    }
  }
  EXPECT_EQ(rackGeneratorOf(0), RackGenerator::Frozen);
  EXPECT_EQ(rackGeneratorOf(1), RackGenerator::Hand);
  EXPECT_FALSE(rackGeneratorOf(2));
  EXPECT_FALSE(rackGeneratorOf(-1));
}

}  // namespace
}  // namespace pool::table
