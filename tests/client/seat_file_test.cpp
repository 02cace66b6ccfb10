// A player's kept seat: written and read back, and taken back only when the player asks for no
// other table.
#include "client/net/seat_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

namespace pool::client {
namespace {

TEST(SeatFileTest, AKeptSeatReadsBackAsWritten) {
  const std::filesystem::path path =
      "/tmp/pool-seat-file-test-" + std::to_string(::getpid()) + ".json";
  const SeatRecord kept{"srv-4", 1, 0xfeedULL, 17};
  ASSERT_EQ(writeSeatFile(path, kept), "");
  const auto read = readSeatFile(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(read) << read.error();
  ASSERT_TRUE(read->has_value());
  EXPECT_EQ((*read)->match, "srv-4");
  EXPECT_EQ((*read)->seat, 1);
  EXPECT_EQ((*read)->token, 0xfeedULL);
  EXPECT_EQ((*read)->last_seq, 17u);
}

// pool-client --practice with a kept seat in a finished match took that seat back and showed its
// game-over screen: asking for a table of one's own, or for another match, is not asking for it.
TEST(SeatFileTest, TheKeptSeatIsTakenBackOnlyWhenNoOtherTableIsAskedFor) {
  const SeatRecord kept{"srv-4", 0, 99, 3};
  EXPECT_TRUE(takesBackKeptSeat(kept, ""));       // --play: wherever there is a seat
  EXPECT_TRUE(takesBackKeptSeat(kept, "srv-4"));  // --play --match srv-4
  EXPECT_FALSE(takesBackKeptSeat(kept, "new"));   // --practice, or New game in the lobby
  EXPECT_FALSE(takesBackKeptSeat(kept, "srv-5"));
}

}  // namespace
}  // namespace pool::client
