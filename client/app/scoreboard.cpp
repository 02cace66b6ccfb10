// The Match pane's words for racks, frames and games, and snooker's scoreboard.
#include "client/app/scoreboard.h"

#include <algorithm>

#include "client/app/spoken.h"
#include "physics/ball.h"
#include "rules/snooker.h"
#include "table/rack.h"

namespace pool::app {
namespace {

std::string counted(int n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string rackWord(rules::Game game) {
  switch (game) {
    case rules::Game::Snooker:
      return "frame";
    case rules::Game::ThreeCushion:
      return "game";
    default:
      return "rack";
  }
}

std::string phaseLine(const client::MatchView& view) {
  return spoken(client::toString(view.phase)) + ", " + rackWord(view.settings.game) + " " +
         std::to_string(view.rack) + ", shot " + std::to_string(view.shot_number);
}

std::string snookerBallName(int id) {
  static const std::array<const char*, 6> kColours{"yellow", "green", "brown",
                                                   "blue",   "pink",  "black"};
  if (id == physics::kCueBall) return "cue ball";
  if (rules::isRed(id)) return "red";
  if (rules::isColour(id)) return kColours[static_cast<std::size_t>(id - table::kSnookerYellow)];
  return "ball " + std::to_string(id);
}

std::string ballOnWords(int ball_on, bool free_ball) {
  std::string on = ball_on == rules::kOnRed      ? "on a red"
                   : ball_on == rules::kOnColour ? "on a colour"
                                                 : "on the " + snookerBallName(ball_on);
  return free_ball ? "free ball, " + on : on;
}

SnookerBoard snookerBoard(const client::MatchView& view) {
  SnookerBoard board;
  for (const auto& b : view.balls) {
    if (rules::isRed(b.id) && physics::onTable(b.state)) ++board.reds_left;
  }
  const rules::GameState state = client::gameStateOf(view);
  board.points_remaining = rules::pointsRemaining(state, view.balls);
  for (int s = 0; s < 2; ++s) {
    board.snookers_required[static_cast<std::size_t>(s)] =
        rules::snookersRequired(state, view.balls, s);
  }
  return board;
}

std::string snookerSeatLine(const client::SeatView& seat) {
  return counted(seat.points, "point", "points") + ", high break " + std::to_string(seat.high_run) +
         ", " + counted(seat.racks_won, "frame", "frames") + " won";
}

std::vector<std::string> snookerLines(const client::MatchView& view, const SeatNames& names) {
  std::vector<std::string> lines;
  if (!client::inPlay(view.phase)) return lines;
  const SnookerBoard board = snookerBoard(view);
  if (view.shooter == 0 || view.shooter == 1) {
    lines.push_back(names[static_cast<std::size_t>(view.shooter)] +
                    (view.free_ball ? " plays a free ball, " : " ") +
                    ballOnWords(view.ball_on, false) +
                    (view.run > 0 ? ", break " + std::to_string(view.run) : ""));
  }
  lines.push_back(counted(board.reds_left, "red", "reds") + " left, " +
                  std::to_string(board.points_remaining) + " points remaining");
  for (std::size_t s = 0; s < 2; ++s) {
    const int short_by = board.snookers_required[s];
    if (short_by > 0) {
      lines.push_back(names[s] + " needs snookers: " + counted(short_by, "point", "points") +
                      " short");
    }
  }
  return lines;
}

std::string raceLine(const client::MatchView& view) {
  const auto& s = view.settings;
  const std::string frames =
      std::to_string(view.seats[0].racks_won) + "-" + std::to_string(view.seats[1].racks_won);
  if (s.game == rules::Game::ThreeCushion) {
    return "three-cushion to " + std::to_string(s.points) + ": " +
           std::to_string(view.seats[0].points) + "-" + std::to_string(view.seats[1].points);
  }
  if (s.game == rules::Game::Snooker) {
    return "snooker, race to " + counted(s.race_to, "frame", "frames") + ": " + frames +
           ", this frame " + std::to_string(view.seats[0].points) + "-" +
           std::to_string(view.seats[1].points);
  }
  return spoken(rules::toString(s.game)) + ", race to " + std::to_string(s.race_to) + ": " + frames;
}

}  // namespace pool::app
