// The Magic Eight Ball: its twenty answers, and a deterministic, well-spread, normalised pick.
#include "client/room/magic_eight_ball.h"

#include <gtest/gtest.h>

#include <set>

namespace pool::room {
namespace {

TEST(MagicEightBallTest, TwentyDistinctAnswersTenYesFiveMaybeFiveNo) {
  const auto& answers = classicAnswers();
  EXPECT_EQ(std::set<std::string_view>(answers.begin(), answers.end()).size(), 20u);
  int kinds[3] = {0, 0, 0};
  for (std::size_t i = 0; i < answers.size(); ++i) ++kinds[static_cast<int>(answerKind(i))];
  EXPECT_EQ(kinds[0], 10);
  EXPECT_EQ(kinds[1], 5);
  EXPECT_EQ(kinds[2], 5);
  EXPECT_EQ(answers[0], "It is certain.");
  EXPECT_EQ(answerKind(19), AnswerKind::Negative);
  EXPECT_EQ(answers[19], "Very doubtful.");
}

TEST(MagicEightBallTest, TheSameQuestionAndSeedGetTheSameAnswerWhateverTheSpacingOrCase) {
  const auto a = answer("Will I win the rematch?", 42);
  ASSERT_TRUE(static_cast<bool>(a)) << a.error();
  EXPECT_EQ(*answer("Will I win the rematch?", 42), *a);
  EXPECT_EQ(*answer("  will i   WIN the rematch? ", 42), *a);
  const auto& all = classicAnswers();
  EXPECT_NE(std::find(all.begin(), all.end(), *a), all.end()) << "one of the twenty";
}

TEST(MagicEightBallTest, SeedsAndQuestionsSpreadOverAllTwentyAnswers) {
  std::set<std::string> by_seed, by_question;
  for (std::uint64_t seed = 0; seed < 400; ++seed) by_seed.insert(*answer("Is it my turn?", seed));
  for (int i = 0; i < 400; ++i) by_question.insert(*answer("Question " + std::to_string(i), 7));
  EXPECT_EQ(by_seed.size(), 20u);
  EXPECT_EQ(by_question.size(), 20u);
}

TEST(MagicEightBallTest, AQuestionWithoutWordsIsRefusedWithAReason) {
  for (const char* blank : {"", "   ", "?!", "\t\n"}) {
    const auto a = answer(blank, 1);
    EXPECT_FALSE(static_cast<bool>(a)) << '"' << blank << '"';
    if (!a) {
      EXPECT_NE(a.error().find("question"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace pool::room
