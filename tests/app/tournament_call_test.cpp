// The tournament match that calls a player: only a match in play that draws their key, once, and
// never while withdrawn or once the tournament is over.
#include "client/app/tournament_call.h"

#include <gtest/gtest.h>

namespace pool::app {
namespace {

std::map<std::string, protocol::TournamentView> field() {
  protocol::TournamentView t;
  t.tournament = "srv-t1";
  t.phase = protocol::TournamentPhase::Running;
  t.entrants = {{"ann", "aa", 1500, 1, 0, false},
                {"bob", "bb", 1500, 2, 0, false},
                {"cid", "cc", 1500, 3, 0, false},
                {"dot", "dd", 1500, 4, 0, false}};
  // Semi-finals 1 v 4 decided, 2 v 3 in play; the final waits.
  t.matches = {{"SF", 0, 3, 3, 0, 1, 0, false, "srv-2"},
               {"SF", 1, 2, 2, -1, 0, 0, false, "srv-3"},
               {"F", 0, -1, 0, -1, 0, 0, false, ""}};
  return {{t.tournament, t}};
}

TEST(TournamentCall, AMatchInPlayCallsBothOfItsPlayersOnce) {
  const auto tournaments = field();
  const auto bob = tournamentCall(tournaments, "bb", {});
  ASSERT_TRUE(bob);
  EXPECT_EQ(bob->tournament, "srv-t1");
  EXPECT_EQ(bob->match, "srv-3");
  EXPECT_EQ(bob->round, "SF");
  EXPECT_EQ(bob->opponent, "cid");
  const auto cid = tournamentCall(tournaments, "cc", {});
  ASSERT_TRUE(cid);
  EXPECT_EQ(cid->opponent, "bob");
  EXPECT_FALSE(tournamentCall(tournaments, "bb", {"srv-3"})) << "joined once already";
  EXPECT_FALSE(tournamentCall(tournaments, "aa", {})) << "ann's final is not ready";
  EXPECT_FALSE(tournamentCall(tournaments, "ee", {})) << "not an entrant";
}

TEST(TournamentCall, NoCallToTheWithdrawnOrOnceItIsOver) {
  auto tournaments = field();
  tournaments["srv-t1"].entrants[1].withdrawn = true;
  EXPECT_FALSE(tournamentCall(tournaments, "bb", {}));
  tournaments = field();
  tournaments["srv-t1"].phase = protocol::TournamentPhase::Cancelled;
  EXPECT_FALSE(tournamentCall(tournaments, "bb", {}));
}

}  // namespace
}  // namespace pool::app
