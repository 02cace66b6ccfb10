// A tournament in the window's words: its line in each phase, its bracket (results, the table of
// a match in play, what comes next) and its entrants by seed with their places.
#include "client/app/tournament_lines.h"

#include <gtest/gtest.h>

namespace pool::app {
namespace {

protocol::TournamentView cup() {
  protocol::TournamentView t;
  t.tournament = "srv-t1";
  t.name = "Friday cup";
  t.capacity = 4;
  t.phase = protocol::TournamentPhase::Running;
  t.entrants = {{"ann", "", 1532, 2, 1, false},
                {"bob", "", 1500, 1, 1, false},
                {"cid", "", 1480, 3, 3, false},
                {"dot", "", 1460, 4, 1, true}};
  t.matches = {{"SF", 1, 3, 3, 1, 0, 0, true, "srv-2"},
               {"SF", 0, 2, 2, -1, 0, 0, false, "srv-3"},
               {"F", 1, -1, 0, -1, 0, 0, false, ""}};
  return t;
}

TEST(TournamentLines, TheLineSaysWhereItStands) {
  auto t = cup();
  EXPECT_EQ(tournamentLine(t),
            "Friday cup: 8-ball, single elimination, race to 1 - running, 1 of 3 matches played");
  t.phase = protocol::TournamentPhase::Entry;
  t.format = protocol::TournamentFormat::RoundRobin;
  t.race_to = 3;
  EXPECT_EQ(tournamentLine(t), "Friday cup: 8-ball, round robin, race to 3 - 4/4 entered");
  t.phase = protocol::TournamentPhase::Finished;
  t.champion = 1;
  EXPECT_EQ(tournamentLine(t), "Friday cup: 8-ball, round robin, race to 3 - won by bob");
  t.handicap = true;
  EXPECT_EQ(tournamentLine(t),
            "Friday cup: 8-ball, round robin, race to 3, handicapped - won by bob");
}

TEST(TournamentLines, AHandicapSaysWhoStartedWithRacks) {
  auto t = cup();
  t.handicap = true;
  t.matches[1].spot_b = 2;
  EXPECT_EQ(bracketLines(t)[1].text, "SF: ann v cid (cid +2) - in play at srv-3");
  t.matches[1].spot_b = 0;
  t.matches[1].spot_a = 1;
  EXPECT_EQ(bracketLines(t)[1].text, "SF: ann v cid (ann +1) - in play at srv-3");
}

TEST(TournamentLines, TheBracketAndTheEntrants) {
  auto t = cup();
  const auto lines = bracketLines(t);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "SF: bob v dot - bob won by forfeit");
  EXPECT_FALSE(lines[0].in_play);
  EXPECT_EQ(lines[1].text, "SF: ann v cid - in play at srv-3");
  EXPECT_TRUE(lines[1].in_play);
  EXPECT_EQ(lines[1].match, "srv-3");
  EXPECT_EQ(lines[2].text, "F: bob v to come - waiting");
  t.matches[1] = {"SF", 0, 2, 3, 2, 1, 2, false, "srv-3"};
  EXPECT_EQ(bracketLines(t)[1].text, "SF: ann v cid - cid won 2-1");
  EXPECT_EQ(entrantLines(t),
            (std::vector<std::string>{"1. bob (1500)", "2. ann (1532)", "3. cid (1480)",
                                      "4. dot (1460), withdrawn"}));
  t.phase = protocol::TournamentPhase::Finished;
  EXPECT_EQ(entrantLines(t)[2], "3. cid (1480), place 3");
}

}  // namespace
}  // namespace pool::app
