// The server's tournaments without the network: entries (only the signing key enters, once;
// forged, unsigned, banned, late and excess entries refused, nothing changed), the matches opened
// with seats only the drawn keys can take, and a restart restoring the tournament from the store.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "server/match_fixture.h"
#include "server/tournament_desk.h"
#include "store/store_fixture.h"

namespace pool::server {
namespace {

using test::keyOf;
using test::nineFoot;
using test::publicKeyOf;

class TournamentDeskTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options_.server_id = "srv";
    options_.protocol_version = protocol::kProtocolVersion;
    auto opened = store::MatchStore::open(scratch_.file("pool.db"));
    ASSERT_TRUE(opened) << opened.error();
    store_ = std::move(*opened);
  }

  /// An entry of `client` (its name and key) into `tournament`, signed by `signer` (default: the
  /// client's own key; another's cannot verify, as a forger's).
  protocol::SeatRequest entry(const std::string& client, const std::string& tournament = "srv-t1",
                              const std::string& signer = {}) {
    protocol::SeatRequest r;
    r.client = client;
    r.protocol_version = protocol::kProtocolVersion;
    r.match = tournament;
    r.action = protocol::JoinAction::Enter;
    r.name = client;
    r.seq = ++seq_;
    protocol::signSeatRequest(r, keyOf(signer.empty() ? client : signer));
    r.public_key = publicKeyOf(client);
    return r;
  }

  /// Enters each of `who` into srv-t1, each from a DDS participant of its own.
  void enterEach(TournamentDesk& desk, std::initializer_list<const char*> who) {
    for (const char* name : who) {
      const auto answer = desk.enter(entry(name), std::string("p-") + name);
      ASSERT_TRUE(answer.accepted()) << name << ": " << answer.reason;
    }
  }

  TournamentSetup cup(int capacity = 4) {
    TournamentSetup s;
    s.name = "Cup";
    s.capacity = capacity;
    return s;
  }

  store::test::Scratch scratch_;
  std::unique_ptr<store::MatchStore> store_;
  RegistryOptions options_;
  std::uint32_t seq_ = 0;
};

TEST_F(TournamentDeskTest, OnlyTheSigningKeyEntersAndOnlyOnce) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  const auto id = desk.create(cup());
  ASSERT_TRUE(id) << id.error();
  ASSERT_EQ(*id, "srv-t1");
  EXPECT_TRUE(desk.enter(entry("ann"), "p1").accepted());
  // Entering again is the same entry (a repeated request), not a second one.
  EXPECT_TRUE(desk.enter(entry("ann"), "p1").accepted());
  // A stranger cannot enter someone else: the request carries bob's key, signed by eve's.
  EXPECT_EQ(desk.enter(entry("bob", "srv-t1", "eve"), "p2").outcome, JoinOutcome::BadSignature);
  auto unsigned_entry = entry("bob");
  unsigned_entry.signature.clear();
  EXPECT_EQ(desk.enter(unsigned_entry, "p2").outcome, JoinOutcome::Unsigned);
  auto old_version = entry("bob");
  old_version.protocol_version = 9;
  protocol::signSeatRequest(old_version, keyOf("bob"));
  EXPECT_EQ(desk.enter(old_version, "p2").outcome, JoinOutcome::VersionMismatch);
  EXPECT_EQ(desk.enter(entry("bob", "srv-t9"), "p2").outcome, JoinOutcome::NoSuchMatch);
  registry.ban(publicKeyOf("bob"), "cheating");
  EXPECT_EQ(desk.enter(entry("bob"), "p2").outcome, JoinOutcome::NotAllowed);
  // One participant may enter two keys (keys cost nothing: a third is refused).
  EXPECT_TRUE(desk.enter(entry("cid"), "p1").accepted());
  const auto third = desk.enter(entry("dot"), "p1");
  EXPECT_EQ(third.outcome, JoinOutcome::NotAllowed);
  EXPECT_EQ(third.reason, "at most 2 entries from one participant");
  const auto views = desk.views();
  ASSERT_EQ(views.size(), 1u);
  ASSERT_EQ(views[0].entrants.size(), 2u);
  EXPECT_EQ(views[0].entrants[0].name, "ann");
  EXPECT_EQ(views[0].entrants[1].name, "cid");
  EXPECT_EQ(views[0].phase, protocol::TournamentPhase::Entry);
}

TEST_F(TournamentDeskTest, AFullTournamentStartsAndReservesEachSeatForItsKey) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  ASSERT_TRUE(desk.create(cup(4)));
  EXPECT_FALSE(desk.start("srv-t1")) << "two entrants are too few";
  for (const char* who : {"ann", "bob", "cid", "dot"}) {
    EXPECT_TRUE(desk.enter(entry(who), std::string("p-") + who).accepted()) << who;
  }
  EXPECT_EQ(desk.enter(entry("eve"), "p-eve").outcome, JoinOutcome::MatchFull);
  desk.step(10.0);
  const auto view = desk.views().front();
  EXPECT_EQ(view.phase, protocol::TournamentPhase::Running);
  ASSERT_EQ(view.matches.size(), 3u);
  int in_play = 0;
  for (const auto& m : view.matches) {
    if (m.state != 2) continue;
    ++in_play;
    Match* table = registry.find(m.match);
    ASSERT_NE(table, nullptr) << m.match;
    EXPECT_TRUE(table->inPlay());
    const auto& a = view.entrants[static_cast<std::size_t>(m.a)];
    const auto& b = view.entrants[static_cast<std::size_t>(m.b)];
    EXPECT_EQ(table->seats()[0].player, a.name);
    EXPECT_EQ(table->seats()[1].player, b.name);
    // Nobody but the drawn key takes a reserved seat; the drawn player gets it back.
    const auto stranger = table->takeSeat(-1, "eve", "eve", 77, publicKeyOf("eve"), std::nullopt);
    EXPECT_FALSE(stranger.accepted());
    const auto drawn = table->takeSeat(-1, a.name, a.name, 78, publicKeyOf(a.name), std::nullopt);
    EXPECT_TRUE(drawn.accepted()) << drawn.reason;
    EXPECT_EQ(drawn.seat, 0);
    EXPECT_TRUE(table->seats()[0].connected());
    EXPECT_FALSE(table->seats()[1].connected()) << "b has not come yet";
  }
  EXPECT_EQ(in_play, 2) << "both semi-finals at once";
  EXPECT_EQ(desk.enter(entry("ann"), "p-ann").outcome, JoinOutcome::Accepted)
      << "an entrant asking again is told it is in";
}

// A drawn player who never sits forfeits once the grace period is over (Match::expireAway), and
// with it the rest of the tournament: withdrawn, the match decided by forfeit, the winner on.
TEST_F(TournamentDeskTest, ANoShowForfeitsTheMatchAndTheRestOfTheTournament) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  ASSERT_TRUE(desk.create(cup(3)));
  ASSERT_NO_FATAL_FAILURE(enterEach(desk, {"ann", "bob", "cid"}));
  desk.step(0.0);
  auto view = desk.views().front();
  const auto played = std::find_if(view.matches.begin(), view.matches.end(),
                                   [](const auto& m) { return m.state == 2; });
  ASSERT_NE(played, view.matches.end());
  const int comes = played->a;
  const int stays_away = played->b;
  Match* table = registry.find(played->match);
  ASSERT_NE(table, nullptr);
  const std::string& name = view.entrants[static_cast<std::size_t>(comes)].name;
  ASSERT_TRUE(table->takeSeat(0, name, name, 5, publicKeyOf(name), std::nullopt).accepted());
  registry.expireAway(61.0, 60.0);
  desk.step(61.0);
  view = desk.views().front();
  const auto& decided = view.matches[static_cast<std::size_t>(played - view.matches.begin())];
  EXPECT_EQ(decided.state, 3);
  EXPECT_TRUE(decided.forfeit);
  EXPECT_EQ(decided.winner, comes);
  EXPECT_TRUE(view.entrants[static_cast<std::size_t>(stays_away)].withdrawn);
  EXPECT_FALSE(view.entrants[static_cast<std::size_t>(comes)].withdrawn);
  // The freed seat stays the drawn player's: a stranger cannot sit and play the table on, and
  // the drawn player coming back late starts no new rack.
  EXPECT_FALSE(table->takeSeat(1, "eve", "eve", 9, publicKeyOf("eve"), std::nullopt).accepted());
  const std::string& late = view.entrants[static_cast<std::size_t>(stays_away)].name;
  EXPECT_TRUE(table->takeSeat(1, late, late, 10, publicKeyOf(late), std::nullopt).accepted());
  EXPECT_EQ(table->phase(), MatchPhase::Over);
}

// Both drawn players gone past the grace: the table is abandoned, both forfeit, and the
// tournament still ends (the bye's entrant wins it).
TEST_F(TournamentDeskTest, ATableBothPlayersLeftEndsInTheirForfeitsAndTheTournamentGoesOn) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  ASSERT_TRUE(desk.create(cup(3)));
  ASSERT_NO_FATAL_FAILURE(enterEach(desk, {"ann", "bob", "cid"}));
  desk.step(0.0);
  registry.expireAway(61.0, 60.0);
  for (double t = 61.0; t < 70.0; t += 1.0) desk.step(t);
  const auto view = desk.views().front();
  EXPECT_EQ(view.phase, protocol::TournamentPhase::Finished);
  ASSERT_GE(view.champion, 0);
  EXPECT_EQ(view.entrants[static_cast<std::size_t>(view.champion)].seed, 1);
}

// Double elimination played through the desk to the grand final's reset (the losers' side wins
// the final): the reset is a match added while results are read, and gets a table of its own.
TEST_F(TournamentDeskTest, ADoubleEliminationReachesTheResetAndEnds) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  auto setup = cup(3);
  setup.format = protocol::TournamentFormat::DoubleElimination;
  ASSERT_TRUE(desk.create(setup));
  ASSERT_NO_FATAL_FAILURE(enterEach(desk, {"ann", "bob", "cid"}));
  double now = 0.0;
  desk.step(now);
  std::set<std::string> tables;
  for (int round = 0;
       round < 20 && desk.views().front().phase == protocol::TournamentPhase::Running; ++round) {
    const auto view = desk.views().front();
    for (const auto& m : view.matches) {
      if (m.state != 2) continue;
      tables.insert(m.match);
      Match* table = registry.find(m.match);
      ASSERT_NE(table, nullptr) << m.match;
      // Both come; then one concedes the race's only rack: entrant a, but for the grand final,
      // where a (the winners' side) concedes so that the reset is played.
      std::array<std::uint64_t, 2> tokens{};
      for (int seat = 0; seat < 2; ++seat) {
        const auto& who = view.entrants[static_cast<std::size_t>(seat == 0 ? m.a : m.b)].name;
        const auto sat = table->takeSeat(seat, who, who, 0, publicKeyOf(who), std::nullopt);
        ASSERT_TRUE(sat.accepted()) << sat.reason;
        tokens[static_cast<std::size_t>(seat)] = sat.token;
      }
      const int loser_seat = m.round == "GF reset" ? 1 : 0;
      const auto& loser = view.entrants[static_cast<std::size_t>(loser_seat == 0 ? m.a : m.b)].name;
      protocol::SeatRequest concede;
      concede.client = loser;
      concede.protocol_version = protocol::kProtocolVersion;
      concede.match = m.match;
      concede.action = protocol::JoinAction::Concede;
      concede.seat = loser_seat;
      concede.token = tokens[static_cast<std::size_t>(loser_seat)];
      concede.seq = ++seq_;
      protocol::signSeatRequest(concede, keyOf(loser));
      const auto conceded = table->seatRequest(concede);
      ASSERT_TRUE(conceded.accepted()) << conceded.reason;
      ASSERT_EQ(table->phase(), MatchPhase::Over);
    }
    desk.step(now += 1.0);
  }
  const auto view = desk.views().front();
  EXPECT_EQ(view.phase, protocol::TournamentPhase::Finished);
  ASSERT_FALSE(view.matches.empty());
  EXPECT_EQ(view.matches.back().round, "GF reset");
  EXPECT_EQ(view.matches.back().state, 3);
  EXPECT_EQ(tables.size(), view.matches.size()) << "each match had a table of its own";
  for (const auto& m : view.matches) EXPECT_FALSE(m.match.empty()) << m.round;
}

TEST_F(TournamentDeskTest, ARestartRestoresTheTournamentFromTheStore) {
  protocol::TournamentView before;
  {
    MatchRegistry registry(options_, nineFoot());
    TournamentDesk desk(registry, store_.get());
    ASSERT_TRUE(desk.create(cup(3)));
    ASSERT_NO_FATAL_FAILURE(enterEach(desk, {"ann", "bob", "cid"}));
    desk.step(1.0);
    before = desk.views().front();
    ASSERT_EQ(before.phase, protocol::TournamentPhase::Running);
  }
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  desk.restore();
  ASSERT_EQ(desk.views().size(), 1u);
  EXPECT_EQ(desk.views().front(), before);
  // Numbers go on from the stored ones.
  const auto next = desk.create(cup());
  ASSERT_TRUE(next) << next.error();
  EXPECT_EQ(*next, "srv-t2");
  // Cancelled: its match in play goes on as an ordinary match.
  const auto going_on = desk.cancel("srv-t1");
  ASSERT_TRUE(going_on) << going_on.error();
  EXPECT_EQ(going_on->size(), 1u);
  EXPECT_EQ(desk.views().front().phase, protocol::TournamentPhase::Cancelled);
  EXPECT_FALSE(desk.cancel("srv-t1"));
}

TEST_F(TournamentDeskTest, APlayerOpensATournamentAndEntersItFirst) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  auto opening = [&](const std::string& who, const std::string& signer = {}) {
    auto r = entry(who, protocol::kNewMatch);
    protocol::MatchSettings settings;
    settings.game = rules::Game::NineBall;
    settings.race_to = 3;
    r.settings = settings;
    r.opening = protocol::TournamentOpening{protocol::TournamentFormat::RoundRobin, 5, true};
    protocol::signSeatRequest(r, keyOf(signer.empty() ? who : signer));
    r.public_key = publicKeyOf(who);
    return r;
  };
  // Opened in someone else's name: the signature is not by the key it carries.
  EXPECT_EQ(desk.enter(opening("ann", "eve"), "p-eve").outcome, JoinOutcome::BadSignature);
  // The opening's fields are signed: a copy with another format does not verify.
  auto altered = opening("ann");
  altered.opening->format = protocol::TournamentFormat::SingleElimination;
  EXPECT_EQ(desk.enter(altered, "p-ann").outcome, JoinOutcome::BadSignature);
  auto without_format = opening("ann");
  without_format.opening.reset();
  protocol::signSeatRequest(without_format, keyOf("ann"));
  EXPECT_EQ(desk.enter(without_format, "p-ann").outcome, JoinOutcome::NotAllowed);
  auto too_many = opening("ann");
  too_many.opening->entrants = 33;
  protocol::signSeatRequest(too_many, keyOf("ann"));
  const auto refused = desk.enter(too_many, "p-ann");
  EXPECT_EQ(refused.outcome, JoinOutcome::NotAllowed);
  EXPECT_EQ(refused.reason, "entrants: 3 to 32");
  EXPECT_TRUE(desk.views().empty()) << "nothing opened by a refused request";

  const auto anns = opening("ann");
  const auto opened = desk.enter(anns, "p-ann");
  ASSERT_TRUE(opened.accepted()) << opened.reason;
  EXPECT_EQ(opened.match, "srv-t1");
  const auto view = desk.views().front();
  EXPECT_EQ(view.name, "ann's cup");
  EXPECT_EQ(view.opened_by, "ann");
  EXPECT_EQ(view.format, protocol::TournamentFormat::RoundRobin);
  EXPECT_EQ(view.game, rules::Game::NineBall);
  EXPECT_EQ(view.race_to, 3);
  EXPECT_EQ(view.capacity, 5);
  EXPECT_TRUE(view.handicap);
  ASSERT_EQ(view.entrants.size(), 1u);
  EXPECT_EQ(view.entrants[0].name, "ann");
  // One taking entries a key, and one a participant.
  const auto again = desk.enter(opening("ann"), "p-ann2");
  EXPECT_EQ(again.reason, "you opened srv-t1, still taking entries: one at a time");
  EXPECT_FALSE(desk.enter(opening("bob"), "p-ann").accepted());
  // Players together hold kPlayerTournamentsOpen taking entries at most.
  for (const char* who : {"bob", "cid", "dot"}) {
    EXPECT_TRUE(desk.enter(opening(who), std::string("p-") + who).accepted()) << who;
  }
  const auto fifth = desk.enter(opening("eve"), "p-eve");
  EXPECT_EQ(fifth.reason, "players have 4 tournaments taking entries already");
  EXPECT_EQ(desk.views().size(), 4u);
  // The same signed request again, from anywhere, opens nothing more: it is srv-t1.
  const auto replayed = desk.enter(anns, "p-eve");
  EXPECT_TRUE(replayed.accepted());
  EXPECT_EQ(replayed.match, "srv-t1");
  EXPECT_EQ(desk.views().size(), 4u);
  // The operator cancels one; its opener may open another (a new request: a new signature).
  ASSERT_TRUE(desk.cancel("srv-t1"));
  EXPECT_EQ(desk.enter(opening("ann"), "p-ann").match, "srv-t5");
  // Stored: a restart knows who opened it and its handicap.
  MatchRegistry registry2(options_, nineFoot());
  TournamentDesk restored(registry2, store_.get());
  restored.restore();
  EXPECT_EQ(restored.views(), desk.views());
}

TEST_F(TournamentDeskTest, APlayersTournamentTakesEntriesForAWhileAndPlayersHoldAFewAtMost) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  auto opening = [&](const std::string& who, int entrants) {
    auto r = entry(who, protocol::kNewMatch);
    r.settings = protocol::MatchSettings{};
    r.opening =
        protocol::TournamentOpening{protocol::TournamentFormat::SingleElimination, entrants, false};
    protocol::signSeatRequest(r, keyOf(who));
    r.public_key = publicKeyOf(who);
    return r;
  };
  ASSERT_TRUE(desk.enter(opening("ann", 8), "p-ann").accepted());  // srv-t1: ann alone
  ASSERT_TRUE(desk.enter(opening("bob", 8), "p-bob").accepted());  // srv-t2: bob, cid, dot
  for (const char* who : {"cid", "dot"}) {
    ASSERT_TRUE(desk.enter(entry(who, "srv-t2"), std::string("p-") + who).accepted());
  }
  desk.step(100.0);
  desk.step(100.0 + kPlayerEntryWindow - 1);
  EXPECT_EQ(desk.views()[0].phase, protocol::TournamentPhase::Entry);
  desk.step(100.0 + kPlayerEntryWindow);
  // Past the window: one entrant is too few (off), three start.
  EXPECT_EQ(desk.views()[0].phase, protocol::TournamentPhase::Cancelled);
  EXPECT_EQ(desk.views()[1].phase, protocol::TournamentPhase::Running);
  // Players' tournaments not over, running ones included, are kPlayerTournamentsNotOver at most:
  // srv-t2 runs; seven more (three entrants each, so they start at once) fill the rest.
  for (int i = 0; i < kPlayerTournamentsNotOver - 1; ++i) {
    const std::string opener = "o" + std::to_string(i);
    const auto opened = desk.enter(opening(opener, 3), "p-" + opener);
    ASSERT_TRUE(opened.accepted()) << opener << ": " << opened.reason;
    for (const char* who : {"x", "y"}) {
      const std::string entrant = who + std::to_string(i);
      ASSERT_TRUE(desk.enter(entry(entrant, opened.match), "p-" + entrant).accepted());
    }
    desk.step(200.0);
  }
  const auto refused = desk.enter(opening("eve", 3), "p-eve");
  EXPECT_EQ(refused.reason, "players have 8 tournaments not over already");
  // The operator's are not counted.
  EXPECT_TRUE(desk.create(cup()));
}

TEST_F(TournamentDeskTest, ARoundRobinTakesNoMoreEntrantsThanItsMatchesCanCross) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  auto setup = cup(12);
  setup.format = protocol::TournamentFormat::RoundRobin;
  const auto refused = desk.create(setup);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(), "entrants: a round robin takes 3 to 11") << "12 play 66 matches";
  setup.capacity = 11;  // 55 matches
  EXPECT_TRUE(desk.create(setup));
}

TEST_F(TournamentDeskTest, AHandicapPutsRacksOnTheWireForTheLowerRated) {
  // Ratings as the store keeps them: ann 1900, the others 1500 (9-ball).
  const auto rate = [&](const char* who, double rating) {
    store_->database()
        .prepare(
            "INSERT INTO ratings(public_key, game, rating, deviation, volatility, matches) "
            "VALUES(?, 9, ?, 60, 0.06, 20)")
        .bindBlob(1, publicKeyOf(who))
        .bind(2, rating)
        .run();
  };
  rate("ann", 1900);
  rate("bob", 1700);
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  auto setup = cup(4);
  setup.game = rules::Game::NineBall;
  setup.race_to = 3;
  setup.handicap = true;
  ASSERT_TRUE(desk.create(setup));
  ASSERT_NO_FATAL_FAILURE(enterEach(desk, {"ann", "bob", "cid", "dot"}));
  desk.step(1.0);
  const auto view = desk.views().front();
  ASSERT_EQ(view.phase, protocol::TournamentPhase::Running);
  // Seeds 1 v 4 (ann 1900 v a fresh 1500) and 2 v 3 (bob 1700 v a fresh 1500); ann and bob's
  // deviations 60, a fresh key's 350. Glickman's expectation with the combined deviation 355.1
  // (g = 0.6637): a fresh 1500 wins a rack from 1700 with p = 0.3178, a race to 3 with 0, 1, 2
  // racks on the wire 0.187, 0.380, 0.682: 1 is nearest even; from 1900, p = 0.1783: 0.043,
  // 0.148, 0.445: 2.
  int checked = 0;
  for (const auto& m : view.matches) {
    if (m.state != 2) continue;
    const auto& a = view.entrants[static_cast<std::size_t>(m.a)];
    const auto& b = view.entrants[static_cast<std::size_t>(m.b)];
    ASSERT_GT(a.rating, b.rating) << "the better seed is a";
    const int spot = a.name == "ann" ? 2 : 1;
    EXPECT_EQ(m.spot_a, 0) << m.round;
    EXPECT_EQ(m.spot_b, spot) << a.name;
    const Match* table = registry.find(m.match);
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->seats()[0].racks_won, 0);
    EXPECT_EQ(table->seats()[1].racks_won, spot) << "the spot is on the table's score";
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST_F(TournamentDeskTest, BadSetupsAreRefused) {
  MatchRegistry registry(options_, nineFoot());
  TournamentDesk desk(registry, store_.get());
  auto bad = cup(2);
  EXPECT_FALSE(desk.create(bad));
  bad = cup(33);
  EXPECT_FALSE(desk.create(bad));
  bad = cup();
  bad.race_to = 0;
  EXPECT_FALSE(desk.create(bad));
  bad = cup();
  bad.name = "";
  EXPECT_FALSE(desk.create(bad));
  EXPECT_TRUE(desk.views().empty());
}

}  // namespace
}  // namespace pool::server
