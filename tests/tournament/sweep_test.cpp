// Every size (3 to 32) and format played out with seeded random winners: the invariants hold.
#include "core/split_mix64.h"
#include "server/tournament/tournament.h"
#include "tournament/field.h"

#include <gtest/gtest.h>

#include <set>

namespace pool::tournament {
namespace {

constexpr Format kFormats[] = {Format::SingleElimination, Format::DoubleElimination,
                               Format::RoundRobin};

struct SweepOutcome {
  int matches = 0;
  bool reset = false;
};

/// Plays `t` to its end: a random ready match starts, and sometimes one more (several tables),
/// then one in play is reported with a random winner and score; with `forfeits`, now and then an
/// entrant leaves. Checks the invariants that hold at every step along the way.
SweepOutcome sweepPlay(Tournament& t, SplitMix64& random, bool forfeits) {
  const int count = static_cast<int>(t.entrants().size());
  for (int step = 0; !t.finished(); ++step) {
    EXPECT_LT(step, 10000) << "no end";
    if (step >= 10000) break;
    if (forfeits && random.below(40) == 0) {
      const int who = static_cast<int>(random.below(count));
      if (!t.withdrawn(who)) {
        EXPECT_TRUE(t.forfeit(who));
      }
      continue;
    }
    std::vector<int> ready = t.readyMatches();
    for (int tables = 1 + static_cast<int>(random.below(3)); tables > 0 && !ready.empty();
         --tables) {
      EXPECT_TRUE(t.start(ready[random.below(ready.size())]));
      ready = t.readyMatches();
    }
    std::vector<int> inPlay;
    std::set<int> busy;
    for (const Match& m : t.matches()) {
      if (m.state != MatchState::InPlay) continue;
      inPlay.push_back(m.index);
      EXPECT_TRUE(busy.insert(m.a).second) << "entrant in two matches";
      EXPECT_TRUE(busy.insert(m.b).second) << "entrant in two matches";
    }
    if (inPlay.empty()) {
      ADD_FAILURE() << "nothing in play or ready before the end";
      break;
    }
    const Match& m = t.matches()[inPlay[random.below(inPlay.size())]];
    const int loserRacks = static_cast<int>(random.below(5));
    const bool aWins = random.below(2) == 0;
    const int index = m.index;
    const int winner = aWins ? m.a : m.b;
    EXPECT_TRUE(t.report(index, winner, aWins ? 5 : loserRacks, aWins ? loserRacks : 5));
  }
  SweepOutcome outcome;
  outcome.matches = static_cast<int>(t.matches().size());
  for (const Match& m : t.matches()) outcome.reset |= m.kind == MatchKind::GrandFinalReset;
  return outcome;
}

/// The invariants of a finished tournament of `count` entrants.
void checkFinished(const Tournament& t, const SweepOutcome& outcome, const std::string& what) {
  const int count = static_cast<int>(t.entrants().size());
  ASSERT_TRUE(t.finished()) << what;
  ASSERT_TRUE(t.champion()) << what;
  EXPECT_TRUE(t.readyMatches().empty()) << what;
  switch (t.format()) {
    case Format::SingleElimination:
      EXPECT_EQ(outcome.matches, count - 1) << what;
      break;
    case Format::DoubleElimination:
      EXPECT_EQ(outcome.matches, outcome.reset ? 2 * count - 1 : 2 * count - 2) << what;
      break;
    case Format::RoundRobin:
      EXPECT_EQ(outcome.matches, count * (count - 1) / 2) << what;
      break;
  }
  std::vector<int> losses(count, 0);
  std::set<int> appear;
  for (const Match& m : t.matches()) {
    EXPECT_EQ(m.state, MatchState::Done) << what << " match " << m.index;
    EXPECT_NE(m.a, m.b) << what;
    appear.insert(m.a);
    appear.insert(m.b);
    ++losses[m.loser()];
  }
  EXPECT_EQ(static_cast<int>(appear.size()), count) << what << ": everyone plays";
  EXPECT_EQ(*appear.begin(), 0) << what;
  const int champion = *t.champion();
  if (t.format() == Format::SingleElimination) {
    for (int e = 0; e < count; ++e) EXPECT_EQ(losses[e], e == champion ? 0 : 1) << what;
  } else if (t.format() == Format::DoubleElimination) {
    for (int e = 0; e < count; ++e) {
      if (e == champion) {
        EXPECT_LE(losses[e], 1) << what;
      } else {
        EXPECT_EQ(losses[e], 2) << what << " entrant " << e;
      }
    }
  }
  // The standings: everyone once, the champion alone in 1st.
  const std::vector<Standing> table = t.standings();
  ASSERT_EQ(static_cast<int>(table.size()), count) << what;
  std::set<int> listed;
  for (const Standing& s : table) listed.insert(s.entrant);
  EXPECT_EQ(static_cast<int>(listed.size()), count) << what;
  EXPECT_EQ(table[0].entrant, champion) << what;
  EXPECT_EQ(table[0].place, 1) << what;
  EXPECT_GT(table[1].place, 1) << what;
  for (std::size_t i = 1; i < table.size(); ++i) EXPECT_LE(table[i - 1].place, table[i].place);
  if (t.format() == Format::RoundRobin) {
    for (int i = 0; i < count; ++i) EXPECT_EQ(table[i].place, i + 1) << what;
  }
}

// N - 1, 2N - 2 or 2N - 1, and N(N-1)/2 matches (each elimination match puts one entrant out, but
// for double elimination's losses in the winners' bracket and the grand final's first; each round-
// robin pair plays once); one champion; everyone plays.
TEST(TournamentSweep, EverySizeAndFormatPlaysToOneChampion) {
  SplitMix64 random(20240601);
  for (const Format format : kFormats) {
    for (int count = kMinEntrants; count <= kMaxEntrants; ++count) {
      for (int run = 0; run < 3; ++run) {
        Tournament t = test::made(format, count);
        const SweepOutcome outcome = sweepPlay(t, random, false);
        checkFinished(t, outcome,
                      "format " + std::to_string(static_cast<int>(format)) + ", " +
                          std::to_string(count) + " entrants, run " + std::to_string(run));
      }
    }
  }
}

// The same with entrants leaving along the way (a forfeit is a match too: the counts hold); each
// finished tournament also survives its JSON round trip.
TEST(TournamentSweep, EverySizeAndFormatWithForfeits) {
  SplitMix64 random(77);
  for (const Format format : kFormats) {
    for (int count = kMinEntrants; count <= kMaxEntrants; ++count) {
      Tournament t = test::made(format, count);
      const SweepOutcome outcome = sweepPlay(t, random, true);
      const std::string what = "format " + std::to_string(static_cast<int>(format)) + ", " +
                               std::to_string(count) + " entrants, forfeits";
      checkFinished(t, outcome, what);
      const Result<Tournament> back = Tournament::fromJson(t.toJson());
      ASSERT_TRUE(back) << what << ": " << back.error();
      EXPECT_EQ(back->toJson(), t.toJson()) << what;
      EXPECT_EQ(back->champion(), t.champion()) << what;
    }
  }
}

}  // namespace
}  // namespace pool::tournament
