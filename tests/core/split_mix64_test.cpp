// SplitMix64 gives the reference sequence, and its uniform and bounded draws stay in range.
#include "core/split_mix64.h"

#include <gtest/gtest.h>

#include <array>

namespace pool {
namespace {

TEST(SplitMix64, SeedsGiveTheReferenceSequence) {
  SplitMix64 rng(1234567);
  const std::array<std::uint64_t, 5> expected{6457827717110365317ULL, 3203168211198807973ULL,
                                              9817491932198370423ULL, 4593380528125082431ULL,
                                              16408922859458223821ULL};
  for (const std::uint64_t e : expected) EXPECT_EQ(rng.next(), e);
  SplitMix64 zero(0);
  EXPECT_EQ(zero.next(), 0xe220a8397b1dcdafULL);
  EXPECT_EQ(zero.next(), 0x6e789e6aa1b965f4ULL);
}

TEST(SplitMix64, TheMixIsTheFirstDrawOfAGeneratorSeededWithIt) {
  for (const std::uint64_t seed : {0ULL, 1ULL, 42ULL, ~0ULL}) {
    SplitMix64 rng(seed);
    EXPECT_EQ(splitMix64(seed), rng.next());
  }
  static_assert(splitMix64(0) == 0xe220a8397b1dcdafULL);
}

TEST(SplitMix64, UniformAndBelowStayInRange) {
  SplitMix64 rng(7);
  std::array<int, 7> counts{};
  for (int i = 0; i < 7000; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const std::uint64_t k = rng.below(7);
    ASSERT_LT(k, 7u);
    ++counts[k];
  }
  for (const int c : counts) EXPECT_GT(c, 800);
}

}  // namespace
}  // namespace pool
