// The per-client join limit: a burst, then a steady rate, per client; idle clients are forgotten.
// The per-period join tally: one summary a period, counts by what happened.
#include <gtest/gtest.h>

#include "server/join_tally.h"
#include "server/match/join_rate_limit.h"

namespace pool::server::test {
namespace {

TEST(JoinRateLimit, ABurstThenTheRateAndEachClientItsOwn) {
  JoinRateLimit limit(10.0, 20.0);
  int allowed = 0;
  for (int i = 0; i < 30; ++i) allowed += limit.allow("a", 5.0) ? 1 : 0;
  EXPECT_EQ(allowed, 20);
  EXPECT_TRUE(limit.allow("b", 5.0)) << "another client has a bucket of its own";
  // 0.35 s later: 3.5 tokens have come back, so three more requests get through.
  allowed = 0;
  for (int i = 0; i < 10; ++i) allowed += limit.allow("a", 5.35) ? 1 : 0;
  EXPECT_EQ(allowed, 3);
}

TEST(JoinRateLimit, IdleAndGoneClientsAreForgotten) {
  JoinRateLimit limit(10.0, 20.0);
  for (int i = 0; i < 1000; ++i) limit.allow("c" + std::to_string(i), 1.0);
  EXPECT_EQ(limit.tracked(), 1000u);
  limit.forget("c0");
  EXPECT_EQ(limit.tracked(), 999u);
  // One token each was taken: full again 0.1 s later, dropped at the next sweep.
  limit.allow("late", 2.5);
  EXPECT_EQ(limit.tracked(), 1u);
}

TEST(JoinRateLimit, ARefusalIsToldOnceASecond) {
  JoinRateLimit limit(20.0, 40.0);
  EXPECT_FALSE(limit.tellRefusal("writer 7", 0.0)) << "nothing to tell a key never seen";
  int allowed = 0, told = 0;
  // 2 000 requests a second for 3 s from one key: 40 at once, then 20 a second, and of the
  // refused ones, one told a second.
  for (int i = 0; i < 6000; ++i) {
    const double now = 10.0 + i / 2000.0;
    if (limit.allow("writer 7", now)) {
      ++allowed;
    } else if (limit.tellRefusal("writer 7", now)) {
      ++told;
    }
  }
  EXPECT_GE(allowed, 40 + 2 * 20);
  EXPECT_LE(allowed, 40 + 3 * 20 + 1);
  EXPECT_EQ(told, 3);
  EXPECT_FALSE(limit.tellRefusal("writer 8", 20.0));
}

TEST(JoinTally, OneSummaryAPeriodWithCountsByWhatHappened) {
  JoinTally tally(1.0);
  EXPECT_FALSE(tally.summary(0.0, 0, 0));
  tally.add("spectate accepted", 10.0);
  tally.add("spectate accepted", 10.2);
  tally.add("gone", 10.4);
  EXPECT_FALSE(tally.summary(10.9, 2, 3)) << "the period is not over";
  const auto line = tally.summary(11.0, 1, 3);
  ASSERT_TRUE(line);
  EXPECT_EQ(*line,
            "joins and leaves in 1.0 s: gone 1, spectate accepted 2 (1 watching, 3 clients "
            "tracked)");
  EXPECT_FALSE(tally.summary(20.0, 0, 0)) << "nothing counted since";
  EXPECT_EQ(tally.total(), 3u);
}

}  // namespace
}  // namespace pool::server::test
