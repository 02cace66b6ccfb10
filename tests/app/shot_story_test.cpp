// Shots, fouls, choices and ends told in sentences with the players' names, never identifiers;
// the help lists every key.
#include "client/app/shot_story.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>

#include "client/app/input.h"
#include "client/app/key_help.h"

namespace pool::app::test {
namespace {

const SeatNames kNames{"Ada", "Bob"};

TEST(ShotStoryTest, AFoulSaysWhoWhyAndWhereTheCueBallGoes) {
  client::ShotReport r;
  r.seat = 0;
  r.fouls = {rules::Foul::CueBallPocketed};
  r.pocketed = {3};
  r.next_shooter = 1;
  r.ball_in_hand = rules::BallInHand::Anywhere;
  EXPECT_EQ(shotStory(r, kNames),
            "Foul by Ada: the cue ball fell in a pocket (a scratch). Down: the 3. Bob to shoot, "
            "with the cue ball in hand anywhere on the table.");
}

TEST(ShotStoryTest, APotKeepsTheTurnAndTheEndNamesTheWinner) {
  client::ShotReport r;
  r.seat = 1;
  r.pocketed = {9, 12, 15};
  r.turn_continues = true;
  r.next_shooter = 1;
  EXPECT_EQ(shotStory(r, kNames), "Bob pocketed the 9, the 12 and the 15. Bob shoots again.");
  r.pocketed = {8};
  r.game_over = true;
  r.winner = 1;
  r.end = rules::GameEnd::EightPocketed;
  EXPECT_EQ(shotStory(r, kNames),
            "Bob pocketed the 8. Game over: Bob wins (the 8 went in the called pocket).");
  r.options = {rules::Choice::PlayOn};
  r.game_over = false;
  r.turn_continues = false;
  r.next_shooter = 0;
  r.pocketed.clear();
  EXPECT_EQ(shotStory(r, kNames),
            "Bob pocketed nothing. Ada to shoot. Ada has a choice to make first.");
}

TEST(ShotStoryTest, NoReasonChoiceOrEndHoldsAnIdentifier) {
  for (const rules::Game game : {rules::Game::EightBall, rules::Game::Snooker}) {
    for (int f = 0; f <= static_cast<int>(rules::Foul::FreeBallSnookers); ++f) {
      const std::string text = foulReason(static_cast<rules::Foul>(f), game);
      EXPECT_EQ(text.find('_'), std::string::npos) << text;
      EXPECT_NE(text, "a foul");
    }
    for (int c = 0; c <= static_cast<int>(rules::Choice::Replace); ++c) {
      const std::string text = choiceSentence(static_cast<rules::Choice>(c), "Bob", game);
      EXPECT_FALSE(text.empty());
      EXPECT_EQ(text.find('_'), std::string::npos) << text;
    }
  }
  for (int e = 0; e <= static_cast<int>(rules::GameEnd::ThreeMisses); ++e) {
    const std::string text = endReason(static_cast<rules::GameEnd>(e));
    EXPECT_EQ(text.find('_'), std::string::npos) << text;
  }
  EXPECT_EQ(choiceSentence(rules::Choice::OpponentReBreaks, "Bob"),
            "Rack the balls again and let Bob break.");
}

// Snooker's story: balls by colour and the points they scored; a foul's points away to the
// opponent and a miss (WPBSA Section 3, 12 and 14), read from the server's verdict; the choices
// in snooker's words; a choice without a stroke; the frame's end.
TEST(ShotStoryTest, SnookerTellsPointsFoulsMissesAndChoices) {
  client::ShotReport r;
  r.seat = 0;
  r.events.resize(1);  // a stroke was played
  r.pocketed = {7, 21};
  r.scored = 8;
  r.turn_continues = true;
  r.next_shooter = 0;
  r.verdict_text = "legal; 8 points; pocketed 7,21; open, seat 0 to shoot";
  EXPECT_EQ(shotStory(r, kNames, rules::Game::Snooker),
            "Ada potted a red and the black: 8 points. Ada plays on.");
  r.pocketed = {3, 9};
  r.scored = 2;
  EXPECT_EQ(shotStory(r, kNames, rules::Game::Snooker),
            "Ada potted two reds: 2 points. Ada plays on.");

  // The cue ball hits nothing: four away, and a miss; Bob chooses.
  r.pocketed.clear();
  r.scored = 0;
  r.turn_continues = false;
  r.next_shooter = 1;
  r.fouls = {rules::Foul::NoBallHit};
  r.options = {rules::Choice::PlayOn, rules::Choice::PassBack, rules::Choice::Replace};
  r.verdict_text =
      "foul no_ball_hit; 4 away; a miss; open, seat 1 to shoot, choose play_on or pass_back or "
      "replace, points 0-4";
  EXPECT_EQ(shotStory(r, kNames, rules::Game::Snooker),
            "Foul and a miss by Ada: the cue ball hit no ball; 4 away to Bob. Bob to shoot. Bob "
            "chooses: play from here, make Ada play again or put the balls back for Ada to play "
            "again.");
  // The pink potted when a red was on, the cue ball in a pocket too: six away, in hand in the D,
  // a free ball offered.
  r.fouls = {rules::Foul::CueBallPocketed, rules::Foul::BallNotOnPocketed};
  r.pocketed = {20};
  r.ball_in_hand = rules::BallInHand::InTheD;
  r.options = {rules::Choice::PlayOn, rules::Choice::FreeBall, rules::Choice::PassBack};
  r.verdict_text = "foul cue_ball_pocketed ball_not_on_pocketed; 6 away; pocketed 20; open";
  EXPECT_EQ(shotStory(r, kNames, rules::Game::Snooker),
            "Foul by Ada: the cue ball fell in a pocket (a scratch); a ball not on fell; 6 away "
            "to Bob. Down: the pink. Bob to shoot, with the cue ball in hand in the D. Bob "
            "chooses: play from here, take a free ball or make Ada play again.");

  // Bob's answer without a stroke: Ada plays again.
  client::ShotReport choice;
  choice.seat = 1;
  choice.next_shooter = 0;
  choice.verdict_text = "legal; open, seat 0 to shoot";
  EXPECT_EQ(shotStory(choice, kNames, rules::Game::Snooker),
            "Bob had Ada play again (Ada to shoot).");

  // The last black: the frame is over.
  client::ShotReport last;
  last.seat = 1;
  last.events.resize(1);
  last.pocketed = {21};
  last.scored = 7;
  last.game_over = true;
  last.winner = 1;
  last.end = rules::GameEnd::FrameOver;
  EXPECT_EQ(shotStory(last, kNames, rules::Game::Snooker),
            "Bob potted the black: 7 points. Frame over: Bob wins it (the frame won on points).");
}

TEST(ShotStoryTest, TheFoulsPointsComeFromTheVerdict) {
  EXPECT_EQ(foulPointsOf("foul wrong_ball_first; 7 away; a miss; open").away, 7);
  EXPECT_TRUE(foulPointsOf("foul wrong_ball_first; 7 away; a miss; open").miss);
  EXPECT_EQ(foulPointsOf("foul no_ball_hit; 4 away; open").away, 4);
  EXPECT_FALSE(foulPointsOf("foul no_ball_hit; 4 away; open").miss);
  EXPECT_EQ(foulPointsOf("legal; 2 points; open").away, 0);
  EXPECT_EQ(foulPointsOf("; 123456789012 away").away, 0) << "no number that long";
  EXPECT_EQ(snookerBallsSaid({16, 5, 17}), "a red, the yellow and the green");
}

TEST(ShotStoryTest, TheServersVerdictReadsWithNames) {
  // The server's seats count from 0; a name with an underscore or a seat number stays as it is.
  EXPECT_EQ(verdictInWords("foul cue_ball_pocketed; open, seat 1 to shoot, ball in hand anywhere",
                           kNames),
            "foul cue ball pocketed; open, Bob to shoot, ball in hand anywhere");
  EXPECT_EQ(verdictInWords("game over, seat 0 wins (eight_on_foul)", {"seat_1", "x"}),
            "game over, seat_1 wins (the 8 pocketed on a foul)");
  EXPECT_EQ(verdictInWords("seat 12 to shoot", kNames), "seat 12 to shoot");
  // A concession, as the server words it (protocol::kConcededTheRack).
  EXPECT_EQ(verdictInWords("seat 1 conceded the rack; rack 2 to break", kNames),
            "Bob conceded the rack; rack 2 to break");
  EXPECT_EQ(verdictInWords("seat 0 conceded the rack: seat 1 won the match", kNames),
            "Ada conceded the rack: Bob won the match");
}

TEST(KeyHelpTest, TheHelpNamesEveryKey) {
  std::string all;
  for (const auto& k : keyHelp()) {
    all += std::string(k.keys) + " " + std::string(k.does) + "\n";
    EXPECT_EQ(std::string(k.does).find('_'), std::string::npos);
  }
  for (const char* name :
       {"LEFT", "RIGHT", "UP", "DOWN", "SPACE", "A",  "Z",         "S", "X",   "G",   "V", "C", "K",
        "P",    "T",     "L",  "B",    "O",     "F1", "R",         "N", "F11", "ESC", "Q", "I", "U",
        "Y",    "J",     "H",  "F5",   "F6",    "F7", "Backspace", "1", "2",   "3",   "4"}) {
    ASSERT_TRUE(std::string(name) == "ESC" || keyFromName(name)) << name;
    std::string word = name;
    std::transform(word.begin() + 1, word.end(), word.begin() + 1,
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    EXPECT_TRUE(std::regex_search(all, std::regex("\\b" + word + "\\b"))) << word;
  }
}

}  // namespace
}  // namespace pool::app::test
