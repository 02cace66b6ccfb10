// The Match pane's facts that differ by game, in words: a rack, a frame or a game; snooker's
// frame score, breaks, ball on, reds left, points remaining and snookers required.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "client/app/shot_story.h"
#include "client/net/match_types.h"
#include "rules/game_rules.h"

namespace pool::app {

/// What one deal of the balls is called: "frame" in snooker, "game" in three-cushion, else
/// "rack".
std::string rackWord(rules::Game game);

/// The Match pane's phase line, e.g. "open, rack 2, shot 7" or "break, frame 1, shot 0".
std::string phaseLine(const client::MatchView& view);

/// A snooker ball by colour: "red" (1–15), "yellow", "green", "brown", "blue", "pink", "black"
/// (16–21), "cue ball" (0).
std::string snookerBallName(int id);

/// Snooker's ball on in words: "on a red", "on a colour", "on the pink"; with a free ball
/// "free ball, on a red".
std::string ballOnWords(int ball_on, bool free_ball);

/// Snooker's facts beyond the seats' own (computed by the rules, rules/snooker.h).
struct SnookerBoard {
  int reds_left = 0;
  int points_remaining = 0;                ///< rules::pointsRemaining
  std::array<int, 2> snookers_required{};  ///< rules::snookersRequired of each seat
};
SnookerBoard snookerBoard(const client::MatchView& view);

/// A snooker seat's line: "23 points, high break 15, 1 frame won".
std::string snookerSeatLine(const client::SeatView& seat);

/// The lines under the seats in a snooker frame in play: who is on what and the break ("Ada on a
/// red, break 15", "Bob plays a free ball, on the pink"), "12 reds left, 123 points remaining", and
/// for a player who needs them "Bob needs snookers: 5 points short" (the rules' snookers required).
std::vector<std::string> snookerLines(const client::MatchView& view, const SeatNames& names);

/// The race's line: "snooker, race to 3 frames: 1-0, this frame 23-8"; for a pool game
/// "9-ball, race to 5: 2-1".
std::string raceLine(const client::MatchView& view);

}  // namespace pool::app
