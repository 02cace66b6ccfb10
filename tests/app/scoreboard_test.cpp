// The Match pane's words by game (a frame, a game, a rack) and snooker's scoreboard: the ball on,
// reds left, points remaining and snookers required (WPBSA Rules, Section 1 and 3, 4-5).
#include "client/app/scoreboard.h"

#include <gtest/gtest.h>

#include "table/rack.h"

namespace pool::app::test {
namespace {

const SeatNames kBoardNames{"Ada", "Bob"};

physics::Ball snookerBallAt(int id, double x) {
  physics::Ball b;
  b.id = id;
  b.pos = Eigen::Vector3d(x, 0.0, 0.02625);
  return b;
}

/// A snooker frame in play with `reds` reds and the colours from `first_colour` to the black.
client::MatchView snookerView(int reds, int first_colour) {
  client::MatchView v;
  v.phase = client::MatchPhase::Open;
  v.settings.game = rules::Game::Snooker;
  v.settings.race_to = 3;
  v.rack = 2;
  v.shot_number = 14;
  v.shooter = 1;
  v.seats[0].name = "Ada";
  v.seats[1].name = "Bob";
  v.balls.push_back(snookerBallAt(0, -1.2));
  for (int id = 1; id <= reds; ++id) v.balls.push_back(snookerBallAt(id, 0.05 * id));
  for (int id = first_colour; id <= table::kSnookerBlack; ++id) {
    v.balls.push_back(snookerBallAt(id, -0.5 + 0.1 * (id - 16)));
  }
  return v;
}

TEST(ScoreboardTest, ARackAFrameOrAGame) {
  client::MatchView v = snookerView(15, 16);
  EXPECT_EQ(phaseLine(v), "open, frame 2, shot 14");
  v.settings.game = rules::Game::ThreeCushion;
  EXPECT_EQ(phaseLine(v), "open, game 2, shot 14");
  v.settings.game = rules::Game::NineBall;
  EXPECT_EQ(phaseLine(v), "open, rack 2, shot 14");
  v.settings.race_to = 5;
  v.seats[0].racks_won = 2;
  v.seats[1].racks_won = 1;
  EXPECT_EQ(raceLine(v), "9-ball, race to 5: 2-1");
}

TEST(ScoreboardTest, TheBallOnInWords) {
  EXPECT_EQ(ballOnWords(rules::kOnRed, false), "on a red");
  EXPECT_EQ(ballOnWords(rules::kOnColour, false), "on a colour");
  EXPECT_EQ(ballOnWords(table::kSnookerPink, false), "on the pink");
  EXPECT_EQ(ballOnWords(table::kSnookerYellow, false), "on the yellow");
  EXPECT_EQ(ballOnWords(rules::kOnRed, true), "free ball, on a red");
  EXPECT_EQ(snookerBallName(7), "red");
  EXPECT_EQ(snookerBallName(table::kSnookerBlack), "black");
  EXPECT_EQ(snookerBallName(0), "cue ball");
}

// Section 1, "points remaining": 8 a red (the red and the black), 27 for the six colours; on a
// colour after a red, 7 more for the black that may follow.
TEST(ScoreboardTest, RedsLeftAndPointsRemaining) {
  client::MatchView v = snookerView(6, 16);
  v.ball_on = rules::kOnRed;
  SnookerBoard board = snookerBoard(v);
  EXPECT_EQ(board.reds_left, 6);
  EXPECT_EQ(board.points_remaining, 6 * 8 + 27);
  v.ball_on = rules::kOnColour;
  EXPECT_EQ(snookerBoard(v).points_remaining, 6 * 8 + 7 + 27);
  // A potted red is off the table: it counts no more.
  v.balls[1].state = physics::MotionState::Pocketed;
  v.ball_on = rules::kOnRed;
  EXPECT_EQ(snookerBoard(v).reds_left, 5);
  EXPECT_EQ(snookerBoard(v).points_remaining, 5 * 8 + 27);
}

// Snookers required: the pink and the black left (13 points), Ada 30 behind: 17 short.
TEST(ScoreboardTest, APlayerTooFarBehindNeedsSnookers) {
  client::MatchView v = snookerView(0, table::kSnookerPink);
  v.ball_on = table::kSnookerPink;
  v.seats[0].points = 10;
  v.seats[1].points = 40;
  v.seats[1].high_run = 31;
  v.seats[0].racks_won = 1;
  v.run = 12;
  const SnookerBoard board = snookerBoard(v);
  EXPECT_EQ(board.reds_left, 0);
  EXPECT_EQ(board.points_remaining, 13);
  EXPECT_EQ(board.snookers_required[0], 17);
  EXPECT_EQ(board.snookers_required[1], 0);
  EXPECT_EQ(
      snookerLines(v, kBoardNames),
      (std::vector<std::string>{"Bob on the pink, break 12", "0 reds left, 13 points remaining",
                                "Ada needs snookers: 17 points short"}));
  EXPECT_EQ(snookerSeatLine(v.seats[0]), "10 points, high break 0, 1 frame won");
  EXPECT_EQ(snookerSeatLine(v.seats[1]), "40 points, high break 31, 0 frames won");
  EXPECT_EQ(raceLine(v), "snooker, race to 3 frames: 1-0, this frame 10-40");
  // 13 behind with 13 on the table: no snookers needed (the black could tie).
  v.seats[0].points = 27;
  EXPECT_EQ(snookerBoard(v).snookers_required[0], 0);
  v.free_ball = true;
  v.run = 0;
  EXPECT_EQ(snookerLines(v, kBoardNames).front(), "Bob plays a free ball, on the pink");
  // Between frames nothing is on.
  v.phase = client::MatchPhase::Over;
  EXPECT_TRUE(snookerLines(v, kBoardNames).empty());
}

}  // namespace
}  // namespace pool::app::test
