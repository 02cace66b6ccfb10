// Shared by the tournament tests: fields of entrants whose seeds are known, and playing matches.
#pragma once

#include "server/tournament/tournament.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace pool::tournament::test {

/// `count` entrants "p0", "p1", ... with falling ratings: entrant i is seed i + 1.
inline std::vector<Entrant> field(int count) {
  std::vector<Entrant> entrants;
  for (int i = 0; i < count; ++i) {
    entrants.push_back({.id = "p" + std::to_string(i),
                        .name = "Player " + std::to_string(i),
                        .rating = 2000.0 - 10.0 * i,
                        .bot = i % 2 == 1});
  }
  return entrants;
}

inline Tournament made(Format format, int count, Options options = {}) {
  Result<Tournament> t = Tournament::create(format, field(count), options);
  EXPECT_TRUE(t) << t.error();
  return std::move(t.value());
}

/// Starts and reports `match` won by `winner` 5-2 (or 2-5).
inline void play(Tournament& t, int match, int winner) {
  ASSERT_TRUE(t.start(match)) << match;
  const Match& m = t.matches()[match];
  const bool aWins = winner == m.a;
  const Check<> reported = t.report(match, winner, aWins ? 5 : 2, aWins ? 2 : 5);
  ASSERT_TRUE(reported) << reported.error();
}

/// Plays every match as it becomes ready, the better seed winning, until none is ready.
inline void playByBetterSeed(Tournament& t) {
  for (std::vector<int> ready = t.readyMatches(); !ready.empty(); ready = t.readyMatches()) {
    const Match& m = t.matches()[ready.front()];
    play(t, m.index, t.seed(m.a) < t.seed(m.b) ? m.a : m.b);
  }
}

}  // namespace pool::tournament::test
