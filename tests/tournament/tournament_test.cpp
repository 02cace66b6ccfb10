// The tournament facade: bad fields refused, bad calls refused, forfeits and cancelling.
#include "server/tournament/tournament.h"
#include "tournament/field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace pool::tournament {
namespace {

using test::field;
using test::made;
using test::play;

std::string createError(std::vector<Entrant> entrants, Options options = {},
                        Format format = Format::SingleElimination) {
  const Result<Tournament> t = Tournament::create(format, std::move(entrants), options);
  return t ? std::string("created") : t.code() + ": " + t.error();
}

// The field's rules (entrant.h): 3 to 32 entrants, distinct non-empty ids, names, finite ratings.
TEST(TournamentCreate, RefusesABadField) {
  EXPECT_EQ(createError(field(3)), "created");
  EXPECT_EQ(createError(field(32)), "created");
  EXPECT_NE(createError(field(2)).find("bad_entrants: "), std::string::npos);
  EXPECT_NE(createError(field(33)).find("33 entrants"), std::string::npos);
  std::vector<Entrant> twice = field(4);
  twice[3].id = twice[1].id;
  EXPECT_NE(createError(twice).find("repeats the id p1"), std::string::npos);
  std::vector<Entrant> unnamed = field(4);
  unnamed[2].name.clear();
  EXPECT_NE(createError(unnamed).find("empty name"), std::string::npos);
  std::vector<Entrant> noId = field(4);
  noId[0].id.clear();
  EXPECT_NE(createError(noId).find("empty id"), std::string::npos);
  std::vector<Entrant> badText = field(4);
  badText[1].name = "bad\xff";
  EXPECT_NE(createError(badText).find("not UTF-8"), std::string::npos);
  std::vector<Entrant> nan = field(4);
  nan[1].rating = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(createError(nan).find("finite rating"), std::string::npos);
  EXPECT_NE(createError(field(4), {.raceTo = -1}).find("bad_options"), std::string::npos);
  EXPECT_NE(createError(field(4), {}, static_cast<Format>(9)).find("unknown format"),
            std::string::npos);
}

// Each refusal of start() and report() by its code (tournament.h); nothing changes on a refusal.
TEST(TournamentCalls, RefusesBadStartsAndReports) {
  Tournament t = made(Format::SingleElimination, 4, {.raceTo = 5});
  // 1v4 is match 0, 2v3 match 1, the final match 2.
  EXPECT_EQ(t.start(-1).code(), "unknown_match");
  EXPECT_EQ(t.start(3).code(), "unknown_match");
  EXPECT_EQ(t.start(2).code(), "not_ready");
  EXPECT_EQ(t.report(0, 0, 5, 2).code(), "not_in_play");
  EXPECT_EQ(t.report(7, 0, 5, 2).code(), "unknown_match");
  ASSERT_TRUE(t.start(0));
  EXPECT_EQ(t.start(0).code(), "in_play");
  EXPECT_EQ(t.report(0, 1, 5, 2).code(), "not_in_match");  // entrant 1 plays match 1
  EXPECT_EQ(t.report(0, 0, -1, 2).code(), "bad_racks");
  EXPECT_EQ(t.report(0, 0, 2, 5).code(), "bad_racks");  // a's winner behind
  EXPECT_EQ(t.report(0, 3, 5, 2).code(), "bad_racks");  // b's winner behind
  EXPECT_EQ(t.report(0, 0, 4, 2).code(), "bad_racks");  // not a race to 5
  EXPECT_EQ(t.report(0, 0, 6, 5).code(), "bad_racks");
  EXPECT_EQ(t.log().size(), 1u);  // only the start
  EXPECT_EQ(t.matches()[0].state, MatchState::InPlay);
  ASSERT_TRUE(t.report(0, 3, 4, 5));  // seed 4 wins 5-4
  EXPECT_EQ(t.report(0, 3, 4, 5).code(), "reported");
  EXPECT_EQ(t.start(0).code(), "reported");
  EXPECT_EQ(t.matches()[2].a, 3);
  play(t, 1, 1);
  play(t, 2, 3);
  EXPECT_EQ(t.champion(), 3);
  EXPECT_EQ(t.start(2).code(), "over");
  EXPECT_EQ(t.forfeit(0).code(), "over");
  EXPECT_EQ(t.cancel().code(), "over");
}

// A forfeit decides the entrant's ready match at once (0-0, marked forfeit) for the other entrant.
TEST(TournamentForfeit, LosesTheReadyMatch) {
  Tournament t = made(Format::SingleElimination, 4);
  const Result<std::vector<int>> decided = t.forfeit(3);  // seed 4, in 1v4
  ASSERT_TRUE(decided) << decided.error();
  EXPECT_EQ(*decided, std::vector<int>{0});
  const Match& m = t.matches()[0];
  EXPECT_EQ(m.state, MatchState::Done);
  EXPECT_EQ(m.winner, 0);
  EXPECT_TRUE(m.forfeit);
  EXPECT_EQ(m.racksA + m.racksB, 0);
  EXPECT_EQ(t.matches()[2].a, 0);
  EXPECT_TRUE(t.withdrawn(3));
  EXPECT_EQ(t.forfeit(3).code(), "withdrawn");
  EXPECT_EQ(t.forfeit(4).code(), "unknown_entrant");
}

// A forfeit in play: the match is decided and answered, so the server can stop it.
TEST(TournamentForfeit, LosesTheMatchInPlay) {
  Tournament t = made(Format::SingleElimination, 4);
  ASSERT_TRUE(t.start(1));  // 2v3
  EXPECT_EQ(*t.forfeit(1), std::vector<int>{1});
  EXPECT_EQ(t.matches()[1].winner, 2);
  EXPECT_EQ(t.matches()[2].b, 2);
}

// Left while waiting for the next opponent: that match is lost as soon as the opponent is known.
TEST(TournamentForfeit, LosesTheNextMatchWhenItIsReady) {
  Tournament t = made(Format::SingleElimination, 4);
  play(t, 0, 0);
  EXPECT_TRUE(t.forfeit(0)->empty());  // the final waits for 2v3
  play(t, 1, 2);
  EXPECT_TRUE(t.finished());
  EXPECT_EQ(t.champion(), 2);
  EXPECT_TRUE(t.matches()[2].forfeit);
  EXPECT_EQ(t.standings()[1].entrant, 0);  // 2nd
}

// Double elimination: one who left loses in the winners' bracket, then again in the losers'.
TEST(TournamentForfeit, DoubleEliminationLosesBothBrackets) {
  Tournament t = made(Format::DoubleElimination, 4);
  play(t, 1, 1);  // 2 beats 3
  // Seed 1 leaves: 1v4 goes to seed 4, and seed 1, dropped into LB R1 against seed 3, loses that
  // at once.
  EXPECT_EQ(*t.forfeit(0), (std::vector<int>{0, 3}));
  EXPECT_EQ(t.matches()[3].state, MatchState::Done);
  EXPECT_TRUE(t.matches()[3].forfeit);
  EXPECT_EQ(t.matches()[3].winner, 2);
  int losses = 0;
  for (const Match& m : t.matches()) losses += m.loser() == 0 ? 1 : 0;
  EXPECT_EQ(losses, 2);
}

// Round robin: every remaining match of the one who left is lost at once; played ones stand.
TEST(TournamentForfeit, RoundRobinLosesEveryRemainingMatch) {
  Tournament t = made(Format::RoundRobin, 5);
  int played = -1;
  for (const Match& m : t.matches()) {
    if (m.has(2)) {
      play(t, m.index, 2);
      played = m.index;
      break;
    }
  }
  ASSERT_GE(played, 0);
  const Result<std::vector<int>> decided = t.forfeit(2);
  EXPECT_EQ(decided->size(), 3u);
  for (const Match& m : t.matches()) {
    if (!m.has(2)) continue;
    EXPECT_EQ(m.state, MatchState::Done);
    EXPECT_EQ(m.winner == 2, m.index == played);
  }
  const auto record = t.standings();
  for (const Standing& s : record) {
    if (s.entrant == 2) {
      EXPECT_EQ(s.wins, 1);
      EXPECT_EQ(s.losses, 3);
    }
  }
}

// Several who left: each match of theirs goes to the one still in; a match between two who left
// (in double elimination, where a forfeit's loser drops into the losers' bracket) to its entrant a.
TEST(TournamentForfeit, TwoWhoLeftMeet) {
  Tournament t = made(Format::SingleElimination, 4);
  ASSERT_TRUE(t.forfeit(1));  // seed 2: 2v3 to seed 3 (entrant 2)
  ASSERT_TRUE(t.forfeit(2));  // seed 3 now waits in the final
  play(t, 0, 3);              // seed 4 beats 1, meets seed 3 who left: seed 4 champion
  EXPECT_EQ(t.champion(), 3);
  Tournament u = made(Format::SingleElimination, 4);
  ASSERT_TRUE(u.forfeit(1));
  ASSERT_TRUE(u.forfeit(2));
  ASSERT_TRUE(u.forfeit(0));  // 1v4 to 4; the final 4 v 3: 3 left
  EXPECT_EQ(u.champion(), 3);
  // Double elimination: seed 4 (entrant 3) loses WB R1 and leaves while waiting in LB R1; seed 2
  // (entrant 1) leaves before 2v3: that loss drops them into LB R1 against seed 4, and the match
  // between the two who left goes to its entrant a, seed 4, who then loses LB R2 by forfeit.
  Tournament w = made(Format::DoubleElimination, 4);
  play(w, 0, 0);
  EXPECT_TRUE(w.forfeit(3)->empty());
  EXPECT_EQ(*w.forfeit(1), (std::vector<int>{1, 3}));
  EXPECT_EQ(w.matches()[3].winner, 3);
  EXPECT_TRUE(w.matches()[3].forfeit);
  play(w, 2, 0);
  EXPECT_EQ(w.matches()[4].winner, 2);
  EXPECT_EQ(w.readyMatches(), std::vector<int>{5});  // the grand final, 1 v 3
}

// Cancel: the matches in play are answered and forgotten (still InPlay; reports refused), nothing
// more is offered, and the tournament has no champion.
TEST(TournamentCancel, ForgetsTheMatchesInPlay) {
  Tournament t = made(Format::SingleElimination, 8);
  ASSERT_TRUE(t.start(0));
  ASSERT_TRUE(t.start(2));
  play(t, 1, 3);
  const Result<std::vector<int>> inPlay = t.cancel();
  ASSERT_TRUE(inPlay);
  EXPECT_EQ(*inPlay, (std::vector<int>{0, 2}));
  EXPECT_TRUE(t.cancelled());
  EXPECT_FALSE(t.finished());
  EXPECT_FALSE(t.champion());
  EXPECT_TRUE(t.readyMatches().empty());
  EXPECT_EQ(t.matches()[0].state, MatchState::InPlay);
  EXPECT_EQ(t.report(0, 0, 5, 2).code(), "over");
  EXPECT_NE(t.report(0, 0, 5, 2).error().find("cancelled"), std::string::npos);
  EXPECT_EQ(t.start(3).code(), "over");
  EXPECT_EQ(t.forfeit(1).code(), "over");
  EXPECT_EQ(t.cancel().code(), "over");
}

}  // namespace
}  // namespace pool::tournament
