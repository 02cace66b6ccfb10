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
  for (int f = 0; f <= static_cast<int>(rules::Foul::BehindHeadStringDirect); ++f) {
    const std::string text = foulReason(static_cast<rules::Foul>(f));
    EXPECT_EQ(text.find('_'), std::string::npos) << text;
    EXPECT_NE(text, "a foul");
  }
  for (int e = 0; e <= static_cast<int>(rules::GameEnd::Forfeit); ++e) {
    const std::string text = endReason(static_cast<rules::GameEnd>(e));
    EXPECT_EQ(text.find('_'), std::string::npos) << text;
  }
  for (int c = 0; c <= static_cast<int>(rules::Choice::OpponentReBreaks); ++c) {
    const std::string text = choiceSentence(static_cast<rules::Choice>(c), "Bob");
    EXPECT_FALSE(text.empty());
    EXPECT_EQ(text.find('_'), std::string::npos) << text;
  }
  EXPECT_EQ(choiceSentence(rules::Choice::OpponentReBreaks, "Bob"),
            "Rack the balls again and let Bob break.");
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
       {"LEFT", "RIGHT", "UP", "DOWN", "SPACE", "A", "Z", "S",  "X",  "G",  "V",
        "C",    "K",     "P",  "T",    "L",     "B", "O", "F1", "R",  "N",  "F11",
        "ESC",  "Q",     "I",  "U",    "Y",     "J", "H", "F5", "F6", "F7", "Backspace"}) {
    ASSERT_TRUE(std::string(name) == "ESC" || keyFromName(name)) << name;
    std::string word = name;
    std::transform(word.begin() + 1, word.end(), word.begin() + 1,
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    EXPECT_TRUE(std::regex_search(all, std::regex("\\b" + word + "\\b"))) << word;
  }
}

}  // namespace
}  // namespace pool::app::test
