// The HUD's words for identifiers: no underscore reaches the screen.
#include "client/app/spoken.h"

#include <gtest/gtest.h>

#include "rules/game_state.h"
#include "rules/placement.h"
#include "rules/verdict.h"

namespace pool::app {
namespace {

TEST(SpokenTest, IdentifiersBecomeWordsAndPhrases) {
  EXPECT_EQ(spoken("foot_right_corner"), "foot right corner");
  EXPECT_EQ(spoken("behind_head_string"), "behind the head string");
  EXPECT_EQ(spoken("eight_on_foul"), "the 8 pocketed on a foul");
  EXPECT_EQ(spoken("open"), "open");
}

TEST(SpokenTest, EveryRuleNameIsSpokenWithoutUnderscores) {
  using namespace pool::rules;
  std::vector<std::string> said;
  for (auto c : {Choice::PlayOn, Choice::BallInHand, Choice::RespotEight, Choice::ReBreak,
                 Choice::OpponentReBreaks}) {
    said.push_back(spoken(toString(c)));
  }
  for (auto e : {GameEnd::EightPocketed, GameEnd::EightOnFoul, GameEnd::EightBeforeGroupCleared,
                 GameEnd::EightWithLastGroupBall, GameEnd::EightWrongPocket, GameEnd::EightOffTable,
                 GameEnd::Forfeit}) {
    said.push_back(spoken(toString(e)));
  }
  for (auto f : {Foul::CueBallPocketed, Foul::CueBallOffTable, Foul::NoBallHit,
                 Foul::WrongBallFirst, Foul::NoCushionAfterContact, Foul::ObjectBallOffTable,
                 Foul::ShotClockExpired, Foul::IllegalBreak, Foul::BehindHeadStringDirect}) {
    said.push_back(spoken(toString(f)));
  }
  said.push_back(spoken(toString(BallInHand::BehindHeadString)));
  for (const std::string& s : said) {
    EXPECT_EQ(s.find('_'), std::string::npos) << s;
    EXPECT_FALSE(s.empty());
  }
}

TEST(SpokenTest, TextKeepsItsWordsAndSpeaksItsIdentifiers) {
  EXPECT_EQ(spokenText("foul: wrong_ball_first; ball in hand behind_head_string."),
            "foul: wrong ball first; ball in hand behind the head string.");
  EXPECT_EQ(spokenText("Ada pocketed the 3 in foot_left_corner"),
            "Ada pocketed the 3 in foot left corner");
  EXPECT_EQ(spokenText("plain text, 12 words"), "plain text, 12 words");
}

}  // namespace
}  // namespace pool::app
