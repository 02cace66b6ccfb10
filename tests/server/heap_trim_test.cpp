// When the server gives a flood's freed heap back: once, after enough join events and a quiet
// spell, and not again until another flood.
#include "server/heap_trim.h"

#include <gtest/gtest.h>

namespace pool::server {
namespace {

TEST(HeapTrim, OnceAFloodIsOverAndNotForAFewJoins) {
  HeapTrim trim;
  // A few joins, then quiet: no flood, nothing to give back.
  EXPECT_FALSE(trim.due(10, 1.0));
  EXPECT_FALSE(trim.due(10, 10.0));
  // A flood: never while the count still moves.
  for (int i = 1; i <= 30; ++i) EXPECT_FALSE(trim.due(10 + 100u * i, 10.0 + 0.1 * i));
  EXPECT_FALSE(trim.due(3010, 13.0 + HeapTrim::kQuiet - 0.5));  // not quiet long enough
  EXPECT_TRUE(trim.due(3010, 13.0 + HeapTrim::kQuiet + 0.1));
  EXPECT_FALSE(trim.due(3010, 30.0)) << "trimmed once per flood";
  // A few more joins later are no new flood; another thousand are.
  EXPECT_FALSE(trim.due(3100, 40.0));
  EXPECT_FALSE(trim.due(3100, 45.0));
  EXPECT_FALSE(trim.due(4100, 50.0));
  EXPECT_TRUE(trim.due(4100, 50.0 + HeapTrim::kQuiet));
}

}  // namespace
}  // namespace pool::server
