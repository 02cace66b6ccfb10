// Single elimination: byes to the top seeds, N - 1 matches, the rounds' names and the places.
#include "server/tournament/tournament.h"
#include "tournament/field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace pool::tournament {
namespace {

using test::field;
using test::made;
using test::play;
using test::playByBetterSeed;

// Five in a bracket of eight: positions 1 8 4 5 2 7 3 6 make 1v8, 4v5, 2v7, 3v6; seeds 6, 7 and 8
// are byes, so seeds 1 to 3 go straight on and the first round is 4v5 alone. Then two semis and a
// final: 4 matches (N - 1).
TEST(SingleElimination, FiveEntrantsGiveThreeByesToTheTopSeeds) {
  const Tournament t = made(Format::SingleElimination, 5);
  ASSERT_EQ(t.matches().size(), 4u);
  const Match& first = t.matches()[0];
  EXPECT_EQ(first.round, "QF");
  EXPECT_EQ(std::set<int>({first.a, first.b}), std::set<int>({3, 4}));  // seeds 4 and 5
  EXPECT_EQ(first.state, MatchState::Ready);
  // Seeds 2 and 3 meet in a semi-final at once; seed 1 waits for 4v5's winner.
  const Match& top = t.matches()[1];
  const Match& bottom = t.matches()[2];
  EXPECT_EQ(top.round, "SF");
  EXPECT_EQ(top.a, 0);
  EXPECT_EQ(top.b, -1);
  EXPECT_EQ(top.state, MatchState::Waiting);
  EXPECT_EQ(std::set<int>({bottom.a, bottom.b}), std::set<int>({1, 2}));
  EXPECT_EQ(t.matches()[3].round, "F");
  EXPECT_EQ(t.readyMatches(), (std::vector<int>{0, 2}));
  // Seeds 1 to 3 (entrants 0 to 2) play no first-round match: a bye is no match.
  for (const Match& m : t.matches()) {
    if (m.round == "QF") {
      EXPECT_FALSE(m.has(0) || m.has(1) || m.has(2));
    }
  }
}

// Eight, the better seed winning every match: 4 + 2 + 1 = 7 matches, seed 1 champion; seed 2 is
// 2nd, the semi-finals' losers (seeds 3 and 4) share 3rd, the quarter-finals' (5 to 8) share 5th.
TEST(SingleElimination, EightPlayedToAChampionInSevenMatches) {
  Tournament t = made(Format::SingleElimination, 8);
  EXPECT_EQ(t.matches().size(), 7u);
  playByBetterSeed(t);
  EXPECT_TRUE(t.finished());
  EXPECT_EQ(t.matches().size(), 7u);
  EXPECT_EQ(t.champion(), 0);
  EXPECT_TRUE(t.readyMatches().empty());
  std::vector<std::string> rounds;
  for (const Match& m : t.matches()) {
    EXPECT_EQ(m.state, MatchState::Done);
    rounds.push_back(m.round);
  }
  EXPECT_EQ(rounds, (std::vector<std::string>{"QF", "QF", "QF", "QF", "SF", "SF", "F"}));
  // The final is seed 1 v seed 2, as the seeding promises.
  EXPECT_EQ(std::set<int>({t.matches()[6].a, t.matches()[6].b}), std::set<int>({0, 1}));
  const std::vector<Standing> table = t.standings();
  ASSERT_EQ(table.size(), 8u);
  const std::vector<int> places = {1, 2, 3, 3, 5, 5, 5, 5};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(table[i].entrant, i);
    EXPECT_EQ(table[i].place, places[i]) << i;
  }
  EXPECT_EQ(table[0].wins, 3);
  EXPECT_EQ(table[0].racksWon, 15);
  EXPECT_EQ(table[0].racksLost, 6);
}

// An upset: seed 8 beats seed 1 and goes on to win; the champion is who won the final.
TEST(SingleElimination, AnUpsetCarriesTheWinnerOn) {
  Tournament t = made(Format::SingleElimination, 8);
  play(t, 0, 7);                   // QF 1v8: seed 8 wins
  EXPECT_EQ(t.matches()[4].a, 7);  // into the top semi-final
  for (std::vector<int> ready = t.readyMatches(); !ready.empty(); ready = t.readyMatches()) {
    const Match& m = t.matches()[ready.front()];
    play(t, m.index, m.has(7) ? 7 : std::min(m.a, m.b));
  }
  EXPECT_EQ(t.champion(), 7);
  EXPECT_EQ(t.standings().front().entrant, 7);
}

}  // namespace
}  // namespace pool::tournament
