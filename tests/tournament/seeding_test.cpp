// Seeding: the field ordered by rating, and the standard bracket order of seeds.
#include "server/tournament/seeding.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace pool::tournament {
namespace {

// The usual bracket, worked by hand: each first-round pair sums to size + 1 (1v8, 2v7, 3v6, 4v5),
// and the halves keep 1 and 2 apart (1 with 4 and 5 on top; 2 with 3 below), the quarters 1 and 4
// from 2 and 3.
TEST(Seeding, BracketOrderOfEight) {
  EXPECT_EQ(bracketOrder(8), (std::vector<int>{1, 8, 4, 5, 2, 7, 3, 6}));
}

// Sixteen, by hand from eight: each seed s of 1 8 4 5 2 7 3 6 is followed by 17 - s.
TEST(Seeding, BracketOrderOfSixteen) {
  EXPECT_EQ(bracketOrder(16),
            (std::vector<int>{1, 16, 8, 9, 4, 13, 5, 12, 2, 15, 7, 10, 3, 14, 6, 11}));
}

// The rule behind the order, for every size up to 32: in each block of 2^r positions (the part of
// the bracket that plays down to one survivor by round r) the best seed is one of the top 2^-r of
// the field, so seeds 1 and 2 sit in different halves, 1 to 4 in different quarters.
TEST(Seeding, BracketOrderKeepsTheTopSeedsApart) {
  for (int size = 2; size <= 32; size *= 2) {
    const std::vector<int> order = bracketOrder(size);
    ASSERT_EQ(static_cast<int>(order.size()), size);
    EXPECT_EQ(std::set<int>(order.begin(), order.end()).size(), order.size());
    for (int block = 2; block <= size; block *= 2) {
      std::set<int> bests;
      for (int start = 0; start < size; start += block) {
        int best = size + 1;
        for (int i = start; i < start + block; ++i) best = std::min(best, order[i]);
        bests.insert(best);
      }
      EXPECT_EQ(*bests.rbegin(), size / block) << size << " " << block;
    }
  }
}

TEST(Seeding, BracketSizeIsTheNextPowerOfTwo) {
  EXPECT_EQ(bracketSize(3), 4);
  EXPECT_EQ(bracketSize(4), 4);
  EXPECT_EQ(bracketSize(5), 8);
  EXPECT_EQ(bracketSize(17), 32);
  EXPECT_EQ(bracketSize(32), 32);
}

// Highest rating first; equal ratings keep the entry order.
TEST(Seeding, SeedOrderByRatingThenEntryOrder) {
  const std::vector<Entrant> entrants = {{.id = "a", .name = "A", .rating = 1500.0},
                                         {.id = "b", .name = "B", .rating = 1700.0},
                                         {.id = "c", .name = "C", .rating = 1500.0},
                                         {.id = "d", .name = "D", .rating = 1800.0}};
  EXPECT_EQ(seedOrder(entrants), (std::vector<int>{3, 1, 0, 2}));
}

}  // namespace
}  // namespace pool::tournament
