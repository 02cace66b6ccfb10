// Double elimination: the losers' bracket, the grand final and its reset, and two losses to be out.
#include "server/tournament/tournament.h"
#include "tournament/field.h"

#include <gtest/gtest.h>

#include <set>

namespace pool::tournament {
namespace {

using test::made;
using test::play;

/// Losses of each entrant over the Done matches.
std::vector<int> lossesOf(const Tournament& t) {
  std::vector<int> losses(t.entrants().size(), 0);
  for (const Match& m : t.matches()) {
    if (m.state == MatchState::Done) ++losses[m.loser()];
  }
  return losses;
}

// Four, by hand: WB R1 is 1v4 (match 0) and 2v3 (match 1), WB R2 their winners (2); LB R1 the WB R1
// losers (3), LB R2 its winner v WB R2's loser (4), then the grand final (5): 2N - 2 = 6 matches.
TEST(DoubleElimination, FourWithoutTheReset) {
  Tournament t = made(Format::DoubleElimination, 4);
  std::vector<std::string> rounds;
  for (const Match& m : t.matches()) rounds.push_back(m.round);
  EXPECT_EQ(rounds, (std::vector<std::string>{"WB R1", "WB R1", "WB R2", "LB R1", "LB R2", "GF"}));
  play(t, 0, 0);  // seed 1 beats 4
  play(t, 1, 1);  // seed 2 beats 3
  EXPECT_EQ(std::set<int>({t.matches()[3].a, t.matches()[3].b}), std::set<int>({2, 3}));
  play(t, 2, 0);  // WB final: 1 beats 2, who drops to LB R2
  play(t, 3, 2);  // LB R1: 3 beats 4: 4 is out with two losses
  EXPECT_EQ(t.matches()[4].a, 2);
  EXPECT_EQ(t.matches()[4].b, 1);
  play(t, 4, 1);                   // LB R2: 2 beats 3
  EXPECT_EQ(t.matches()[5].a, 0);  // the winners' bracket champion
  EXPECT_EQ(t.matches()[5].b, 1);  // the losers' bracket's
  EXPECT_EQ(t.matches()[5].kind, MatchKind::GrandFinal);
  play(t, 5, 0);  // the unbeaten seed 1 wins the grand final: no reset
  EXPECT_TRUE(t.finished());
  EXPECT_EQ(t.champion(), 0);
  EXPECT_EQ(t.matches().size(), 6u);
  EXPECT_EQ(lossesOf(t), (std::vector<int>{0, 2, 2, 2}));
  const std::vector<Standing> table = t.standings();
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(table[i].entrant, i);
    EXPECT_EQ(table[i].place, i + 1);
  }
}

// The same, but seed 2 (from the losers' bracket) wins the grand final: that is seed 1's first
// loss, so a reset is played (7 matches = 2N - 1), and seed 2 wins that too.
TEST(DoubleElimination, FourWithTheReset) {
  Tournament t = made(Format::DoubleElimination, 4);
  play(t, 0, 0);
  play(t, 1, 1);
  play(t, 2, 0);
  play(t, 3, 2);
  play(t, 4, 1);
  play(t, 5, 1);  // seed 2 wins the grand final
  EXPECT_FALSE(t.finished());
  ASSERT_EQ(t.matches().size(), 7u);
  const Match& reset = t.matches()[6];
  EXPECT_EQ(reset.round, "GF reset");
  EXPECT_EQ(reset.kind, MatchKind::GrandFinalReset);
  EXPECT_EQ(reset.a, 0);
  EXPECT_EQ(reset.b, 1);
  EXPECT_EQ(t.readyMatches(), std::vector<int>{6});
  EXPECT_EQ(t.standings().front().place, 1);  // both still in: both 1st for now
  EXPECT_EQ(t.standings()[1].place, 1);
  play(t, 6, 1);
  EXPECT_TRUE(t.finished());
  EXPECT_EQ(t.champion(), 1);
  EXPECT_EQ(lossesOf(t), (std::vector<int>{2, 1, 2, 2}));
  const std::vector<Standing> table = t.standings();
  EXPECT_EQ(table[0].entrant, 1);
  EXPECT_EQ(table[1].entrant, 0);
  EXPECT_EQ(table[1].place, 2);
}

// Seed 1 wins the grand final's reset: champion after losing once.
TEST(DoubleElimination, TheResetWonByTheWinnersBracketChampion) {
  Tournament t = made(Format::DoubleElimination, 4);
  for (const auto& [match, winner] :
       std::vector<std::pair<int, int>>{{0, 0}, {1, 1}, {2, 0}, {3, 2}, {4, 1}, {5, 1}, {6, 0}}) {
    play(t, match, winner);
  }
  EXPECT_EQ(t.champion(), 0);
  EXPECT_EQ(t.matches().size(), 7u);
  EXPECT_EQ(lossesOf(t), (std::vector<int>{1, 2, 2, 2}));
}

// Nobody is out before two losses: at every step of eight entrants played with upsets, an entrant
// who has no match left to play (nothing Waiting, Ready or InPlay holds them, nor will) has lost
// twice, or is the champion. Checked at the end: every entrant but the champion lost exactly twice.
TEST(DoubleElimination, NobodyOutBeforeTwoLosses) {
  Tournament t = made(Format::DoubleElimination, 8);
  int step = 0;
  for (std::vector<int> ready = t.readyMatches(); !ready.empty(); ready = t.readyMatches()) {
    const Match& m = t.matches()[ready.front()];
    play(t, m.index, ++step % 3 == 0 ? std::max(m.a, m.b) : std::min(m.a, m.b));
  }
  ASSERT_TRUE(t.finished());
  const std::vector<int> losses = lossesOf(t);
  for (int e = 0; e < 8; ++e) {
    if (e == *t.champion()) {
      EXPECT_LE(losses[e], 1);
    } else {
      EXPECT_EQ(losses[e], 2) << e;
    }
  }
}

}  // namespace
}  // namespace pool::tournament
