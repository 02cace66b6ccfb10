// What happened on a shot, said in sentences with the players' names: what fell, the foul and
// its reason, who shoots next and with the cue ball in hand where, the choice to make, the end of
// the game. No identifier reaches these sentences.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "client/net/match_types.h"
#include "rules/game_rules.h"
#include "rules/game_state.h"
#include "rules/verdict.h"

namespace pool::app {

/// The two players' names as shown: a seat's name, or "Player 1" / "Player 2" when it has none.
using SeatNames = std::array<std::string, 2>;
SeatNames seatNames(const client::MatchView* view);

/// Why a foul is one, e.g. "the cue ball fell in a pocket (a scratch)"; in snooker's words for
/// snooker ("the first ball hit was not a ball on").
std::string foulReason(rules::Foul foul, rules::Game game = rules::Game::EightBall);

/// Why a game ended, e.g. "the 8 fell on a foul".
std::string endReason(rules::GameEnd end);

/// Where the cue ball may go, e.g. "anywhere on the table"; empty for none.
std::string inHandWhere(rules::BallInHand in_hand);

/// A choice the rules offer `chooser` explained as a sentence (`other`: the opponent's name), in
/// snooker's words for snooker ("Play from here: ...", "Put the balls back: ...").
std::string choiceSentence(rules::Choice choice, const std::string& other,
                           rules::Game game = rules::Game::EightBall);

/// Snooker's balls in words, e.g. "two reds and the pink" (reds first, then each colour).
std::string snookerBallsSaid(const std::vector<int>& ids);

/// The points a snooker foul gave away and whether it was a miss, read from the server's verdict
/// (rules::describe: "...; 4 away; a miss; ..."); 0 and false when it says neither.
struct FoulPoints {
  int away = 0;
  bool miss = false;
};
FoulPoints foulPointsOf(const std::string& verdict_text);

/// The story of a shot from its final report, e.g. "Foul by Ada: the cue ball fell in a pocket
/// (a scratch). Bob has the cue ball in hand anywhere on the table."
/// `game`: three-cushion tells a point or none where pool tells the balls down; snooker tells the
/// balls by colour and the points scored, a foul's points away and a miss, a choice without a
/// stroke, and the choices in its own words (play from here, a free ball, play again, the balls
/// put back).
std::string shotStory(const client::ShotReport& report, const SeatNames& names,
                      rules::Game game = rules::Game::EightBall);

/// The server's one-line verdict (a late joiner's only account of the last shot) with seat
/// numbers as names and identifiers as words.
std::string verdictInWords(const std::string& verdict, const SeatNames& names);

}  // namespace pool::app
