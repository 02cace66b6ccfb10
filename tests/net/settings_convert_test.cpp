// Match settings through the wire module: lobby entries, match states and seat requests keep them;
// a sample with settings out of range is refused.
#include <gtest/gtest.h>

#include "net/message_convert.h"
#include "net/messages.h"
#include "net/wire_fields.h"

namespace pool::net {
namespace {

protocol::MatchSettings tenBall() {
  protocol::MatchSettings s;
  s.game = rules::Game::TenBall;
  s.race_to = 5;
  s.breaks = protocol::BreakOrder::Winner;
  s.shot_clock = 35.0;
  return s;
}

TEST(SettingsConvert, LobbyEntryKeepsSettingsAndScore) {
  protocol::LobbyEntry entry;
  entry.match = "srv-1";
  entry.settings = tenBall();
  entry.racks_won = {2, 4};
  entry.ratings = {1662, 1338};
  entry.rack = 3;
  entry.shot_number = 41;
  entry.rack_points = {57, 12};
  const auto sample = toWire(entry);  // owns the sequences the wire sample points into
  const pool_MatchInfo& wire = *sample;
  EXPECT_EQ(wire.game, 10);
  const auto back = fromWire(wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->settings, tenBall());
  EXPECT_EQ(back->racks_won, (std::array<int, 2>{2, 4}));
  EXPECT_EQ(back->ratings, (std::array<int, 2>{1662, 1338}));
  EXPECT_EQ(back->rack, 3u);
  EXPECT_EQ(back->shot_number, 41u);
  EXPECT_EQ(back->rack_points, (std::array<int, 2>{57, 12}));
}

TEST(SettingsConvert, MatchStateKeepsSnookersBallOnFreeBallAndMisses) {
  protocol::MatchView view;
  view.match = "srv-1";
  view.settings.game = rules::Game::Snooker;
  view.phase = protocol::MatchPhase::Open;
  view.ball_on = 20;  // the pink
  view.free_ball = true;
  view.ball_in_hand = rules::BallInHand::InTheD;
  view.options = {rules::Choice::PlayOn, rules::Choice::FreeBall, rules::Choice::PassBack,
                  rules::Choice::Replace};
  view.seats[1].misses = 2;
  view.seats[0].points = 47;
  view.run = 12;
  const auto sample = toWire(view);
  EXPECT_EQ(sample->game, 22);
  const auto back = fromWire(*sample);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->settings.game, rules::Game::Snooker);
  EXPECT_EQ(back->ball_on, 20);
  EXPECT_TRUE(back->free_ball);
  EXPECT_EQ(back->ball_in_hand, rules::BallInHand::InTheD);
  EXPECT_EQ(back->options, view.options);
  EXPECT_EQ(back->seats[1].misses, 2);
  EXPECT_EQ(back->seats[0].points, 47);
  EXPECT_EQ(back->run, 12);
  // A ball on past the last ball id is refused.
  auto bad = toWire(view);
  bad->ball_on = 22;
  EXPECT_FALSE(fromWire(*bad));
}

TEST(SettingsConvert, MatchStateKeepsSettingsClockAndFouls) {
  protocol::MatchView view;
  view.match = "srv-1";
  view.settings = tenBall();
  view.shot_clock = 8.0;
  view.shot_clock_total = 70.0;
  view.seats[1].extensions_left = 1;
  view.seats[0].fouls_in_row = 2;
  view.options = {rules::Choice::PlayOn, rules::Choice::PassBack};
  view.end = rules::GameEnd::ThreeFouls;
  const auto wire = toWire(view);
  EXPECT_TRUE(wire->shot_clock_warning);  // 8 s left of a 35 s clock
  const auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->settings, tenBall());
  EXPECT_DOUBLE_EQ(back->shot_clock_total, 70.0);
  EXPECT_EQ(back->seats[1].extensions_left, 1);
  EXPECT_EQ(back->seats[0].fouls_in_row, 2);
  EXPECT_EQ(back->options, view.options);
  EXPECT_EQ(back->end, rules::GameEnd::ThreeFouls);
  EXPECT_TRUE(back->clockWarning());
}

TEST(SettingsConvert, SeatRequestSettingsInAndBadOnesRefused) {
  protocol::SeatRequest r;
  r.client = "c0ffee";
  r.match = "new";
  r.name = "Ada";
  r.settings = tenBall();
  auto wire = toWire(r);
  EXPECT_TRUE(wire->has_settings);
  auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->settings, tenBall());

  wire->game = 7;
  EXPECT_EQ(fromWire(*wire).error(), "settings: game: must be 8, 9, 10 or 3 (three-cushion)");
  // Three-cushion (3) takes its points from the request: 1-100.
  wire->game = 3;
  wire->points = 0;
  EXPECT_EQ(fromWire(*wire).error(), "settings: points: must be 1 to 100 points");
  wire->points = 7;
  ASSERT_TRUE(fromWire(*wire));
  EXPECT_EQ(fromWire(*wire)->settings->points, 7);
  EXPECT_EQ(fromWire(*wire)->settings->game, rules::Game::ThreeCushion);
  wire->game = 9;
  wire->race_to = 0;
  EXPECT_FALSE(fromWire(*wire));
  wire->race_to = 3;
  wire->shot_clock = 1.0;
  EXPECT_FALSE(fromWire(*wire));
  wire->shot_clock = 0.0;
  setRawValue(wire->breaks, 7);
  EXPECT_FALSE(fromWire(*wire));
  // Without settings the fields are not read.
  wire->has_settings = false;
  back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_FALSE(back->settings);
}

}  // namespace
}  // namespace pool::net
