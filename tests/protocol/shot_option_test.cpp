// The one mapping between the rules' choices and the protocol's shot options.
#include <gtest/gtest.h>

#include <set>

#include "protocol/shot_request.h"

namespace pool::protocol {
namespace {

// Every choice the rules can offer, listed here by hand so that a choice added to the rules and
// not to this list (or to the mapping) is noticed: the count is checked against the enum's last.
const rules::Choice kChoices[] = {rules::Choice::PlayOn,           rules::Choice::BallInHand,
                                  rules::Choice::RespotEight,      rules::Choice::ReBreak,
                                  rules::Choice::OpponentReBreaks, rules::Choice::PushOut,
                                  rules::Choice::PassBack};

TEST(ShotOptionTest, EveryChoiceHasItsOwnOptionAndComesBackFromIt) {
  static_assert(std::size(kChoices) == static_cast<std::size_t>(rules::Choice::PassBack) + 1);
  std::set<ShotOption> seen;
  for (const auto choice : kChoices) {
    const ShotOption option = optionOf(choice);
    EXPECT_NE(option, ShotOption::None) << static_cast<int>(choice);
    EXPECT_TRUE(seen.insert(option).second) << "two choices share " << toString(option);
    ASSERT_TRUE(choiceOf(option).has_value()) << toString(option);
    EXPECT_EQ(*choiceOf(option), choice) << toString(option);
  }
  EXPECT_FALSE(choiceOf(ShotOption::None).has_value());
}

// docs/PROTOCOL.md: a re-rack (either breaker) and a pass-back carry no shot; every other option
// answers with the shot in the same command.
TEST(ShotOptionTest, TheOptionsThatCarryNoShotAreTheReRacksAndThePassBack) {
  for (const auto choice : kChoices) {
    const bool no_shot = choice == rules::Choice::ReBreak ||
                         choice == rules::Choice::OpponentReBreaks ||
                         choice == rules::Choice::PassBack;
    EXPECT_EQ(optionShoots(optionOf(choice)), !no_shot) << toString(optionOf(choice));
  }
  EXPECT_TRUE(optionShoots(ShotOption::None));
}

}  // namespace
}  // namespace pool::protocol
