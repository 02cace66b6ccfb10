// The window's Players table: a player's rating and counts in short columns.
#include "client/app/player_columns.h"

#include <gtest/gtest.h>

namespace pool::app {
namespace {

TEST(PlayerColumns, ARowSaysTheRatingTheRecordAndThePotShare) {
  protocol::PlayerStats s;
  s.server = "srv";
  s.name = "Ada";
  s.game = rules::Game::NineBall;
  s.rating = 1562;
  s.rating_deviation = 80;
  s.matches = 3;
  s.matches_won = 2;
  s.racks = 7;
  s.racks_won = 5;
  s.pots = 45;
  s.attempts = 60;
  s.breaks = 4;
  s.break_pots = 6;
  s.break_and_runs = 1;
  s.fouls = 3;
  s.safeties = 2;
  s.high_run = 8;
  const auto row = playerColumns(s);
  const std::array<std::string, kPlayerColumns> want{
      "srv",         "Ada", "9-ball", "1562 ±80", "2/3", "5/7", "45/60, 0.75 an attempt",
      "4: 6, 1 run", "3",   "2",      "8"};
  EXPECT_EQ(row, want);
  EXPECT_EQ(playerHeaders().size(), row.size());
  // Balls or points an attempt, never a share past 100 % (one stroke may pot two balls; snooker
  // counts points).
  s.game = rules::Game::Snooker;
  s.pots = 145;
  s.attempts = 90;
  EXPECT_EQ(playerColumns(s)[6], "145/90, 1.61 an attempt");
  // No attempts yet: no share.
  s.attempts = 0;
  s.pots = 0;
  EXPECT_EQ(playerColumns(s)[6], "0/0");
}

}  // namespace
}  // namespace pool::app
