// Round robin: the circle method's schedule, and the ranking's tie-breaks.
#include "server/tournament/round_robin.h"
#include "server/tournament/tournament.h"
#include "tournament/field.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace pool::tournament {
namespace {

using test::made;

/// Plays the match between entrants x and y (either side) to x's racks and y's.
void playPair(Tournament& t, int x, int y, int xRacks, int yRacks) {
  for (const Match& m : t.matches()) {
    if (!m.has(x) || !m.has(y)) continue;
    ASSERT_TRUE(t.start(m.index));
    const int index = m.index;
    const bool xIsA = m.a == x;
    const Check<> c =
        t.report(index, xRacks > yRacks ? x : y, xIsA ? xRacks : yRacks, xIsA ? yRacks : xRacks);
    ASSERT_TRUE(c) << c.error();
    return;
  }
  FAIL() << "no match " << x << " v " << y;
}

std::vector<int> rankedEntrants(const Tournament& t) {
  std::vector<int> order;
  for (const Standing& s : t.standings()) order.push_back(s.entrant);
  return order;
}

// Five (odd: a bye each round): C(5,2) = 10 matches in 5 rounds of two, each pair exactly once,
// nobody twice in a round, and each entrant sits out exactly one round.
TEST(RoundRobin, FiveMeetEachOtherOnce) {
  const Tournament t = made(Format::RoundRobin, 5);
  ASSERT_EQ(t.matches().size(), 10u);
  std::set<std::pair<int, int>> pairs;
  std::map<std::string, std::set<int>> byRound;
  std::map<int, int> played;
  for (const Match& m : t.matches()) {
    EXPECT_EQ(m.state, MatchState::Ready);
    EXPECT_NE(m.a, m.b);
    EXPECT_TRUE(pairs.insert({std::min(m.a, m.b), std::max(m.a, m.b)}).second);
    EXPECT_TRUE(byRound[m.round].insert(m.a).second) << m.round;
    EXPECT_TRUE(byRound[m.round].insert(m.b).second) << m.round;
    ++played[m.a];
    ++played[m.b];
  }
  EXPECT_EQ(pairs.size(), 10u);
  EXPECT_EQ(byRound.size(), 5u);
  for (const auto& [round, entrants] : byRound) EXPECT_EQ(entrants.size(), 4u) << round;
  for (int e = 0; e < 5; ++e) EXPECT_EQ(played[e], 4);
}

// Six (even): 15 matches in 5 rounds of three, everyone plays every round.
TEST(RoundRobin, SixPlayEveryRound) {
  const Tournament t = made(Format::RoundRobin, 6);
  ASSERT_EQ(t.matches().size(), 15u);
  std::map<std::string, std::set<int>> byRound;
  for (const Match& m : t.matches()) {
    byRound[m.round].insert(m.a);
    byRound[m.round].insert(m.b);
  }
  EXPECT_EQ(byRound.size(), 5u);
  for (const auto& [round, entrants] : byRound) EXPECT_EQ(entrants.size(), 6u) << round;
}

// An entrant in play is not offered another match at the same time, nor can one be started.
TEST(RoundRobin, NobodyPlaysTwoMatchesAtOnce) {
  Tournament t = made(Format::RoundRobin, 4);
  EXPECT_EQ(t.readyMatches().size(), 6u);
  ASSERT_TRUE(t.start(0));
  const Match& first = t.matches()[0];
  for (const int i : t.readyMatches()) {
    EXPECT_FALSE(t.matches()[i].has(first.a) || t.matches()[i].has(first.b));
  }
  for (const Match& m : t.matches()) {
    if (m.index != 0 && (m.has(first.a) || m.has(first.b))) {
      EXPECT_EQ(t.start(m.index).code(), "entrant_busy");
    }
  }
}

// Rule (round_robin.h): wins, then the wins among those level on wins, then rack difference, then
// seed. Two level: their head-to-head decides, though rack difference says the opposite.
// 0 beats 2 5-0 and 3 5-0 but loses to 1 4-5: 2 wins, difference +9.
// 1 beats 0 5-4 and 2 5-4, loses to 3 0-5: 2 wins, difference -3.
// 2 beats 3 5-4: 1 win, difference -5; 3 beats 1 5-0: 1 win, difference -1.
// So 1 (beat 0) above 0, and 2 (beat 3) above 3.
TEST(RoundRobin, HeadToHeadBreaksATieOfTwo) {
  Tournament t = made(Format::RoundRobin, 4, {.raceTo = 5});
  playPair(t, 0, 2, 5, 0);
  playPair(t, 0, 3, 5, 0);
  playPair(t, 1, 0, 5, 4);
  playPair(t, 1, 2, 5, 4);
  playPair(t, 3, 1, 5, 0);
  playPair(t, 2, 3, 5, 4);
  ASSERT_TRUE(t.finished());
  EXPECT_EQ(rankedEntrants(t), (std::vector<int>{1, 0, 2, 3}));
  EXPECT_EQ(t.champion(), 1);
  const Standing top = t.standings().front();
  EXPECT_EQ(top.wins, 2);
  EXPECT_EQ(top.racksWon - top.racksLost, -3);
}

// Three level on two wins (of five entrants): the mini-table among the three decides (0 beat 1
// and 2; 1 beat 2), though their rack differences (0: -8, 1: -4, 2: +8) say the opposite.
// 4 has three wins, 3 one.
TEST(RoundRobin, MiniTableBreaksATieOfThree) {
  Tournament t = made(Format::RoundRobin, 5, {.raceTo = 5});
  playPair(t, 0, 1, 5, 4);
  playPair(t, 0, 2, 5, 4);
  playPair(t, 3, 0, 5, 0);
  playPair(t, 4, 0, 5, 0);
  playPair(t, 1, 2, 5, 4);
  playPair(t, 1, 3, 5, 4);
  playPair(t, 4, 1, 5, 0);
  playPair(t, 2, 3, 5, 0);
  playPair(t, 2, 4, 5, 0);
  playPair(t, 4, 3, 5, 0);
  ASSERT_TRUE(t.finished());
  EXPECT_EQ(rankedEntrants(t), (std::vector<int>{4, 0, 1, 2, 3}));
}

// Three level on wins in a cycle (0 beat 1, 1 beat 2, 2 beat 0; all beat 3): the mini-table is
// level too, so rack difference decides: 1 (+8) above 0 (+6) above 2 (+1).
TEST(RoundRobin, RackDifferenceBreaksACycle) {
  Tournament t = made(Format::RoundRobin, 4, {.raceTo = 5});
  playPair(t, 0, 1, 5, 3);
  playPair(t, 1, 2, 5, 0);
  playPair(t, 2, 0, 5, 4);
  for (int e = 0; e < 3; ++e) playPair(t, e, 3, 5, 0);
  EXPECT_EQ(rankedEntrants(t), (std::vector<int>{1, 0, 2, 3}));
}

// All keys level (a cycle of three, each won 5-3): the better seed first. Ratings make entry
// order differ from seeds: entrant 1 is seed 1, 2 seed 2, 0 seed 3.
TEST(RoundRobin, SeedBreaksWhatIsLeft) {
  std::vector<Entrant> entrants = test::field(3);
  entrants[0].rating = 1000.0;
  entrants[1].rating = 1200.0;
  entrants[2].rating = 1100.0;
  Result<Tournament> made3 = Tournament::create(Format::RoundRobin, entrants);
  ASSERT_TRUE(made3);
  Tournament& t = made3.value();
  playPair(t, 0, 1, 5, 3);
  playPair(t, 1, 2, 5, 3);
  playPair(t, 2, 0, 5, 3);
  EXPECT_EQ(rankedEntrants(t), (std::vector<int>{1, 2, 0}));
  EXPECT_EQ(t.champion(), 1);
}

}  // namespace
}  // namespace pool::tournament
