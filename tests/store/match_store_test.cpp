// Matches and shots through the store: what is written reads back the same, a match resumes from
// it, and the audit finds a tampered log.
#include <gtest/gtest.h>

#include "server/match_fixture.h"
#include "server/store/match_audit.h"
#include "server/store/match_store.h"
#include "server/store/record_json.h"
#include "store_fixture.h"
#include "stored_break.h"

namespace pool::store::test {
namespace {

using server::test::breakShot;
using server::test::finishNow;
using server::test::kToken0;
using server::test::kToken1;
using server::test::nineFoot;
using server::test::runner;

void expectSameMatch(const server::MatchSnapshot& a, const server::MatchSnapshot& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.rack_seed, b.rack_seed);
  EXPECT_EQ(a.layouts, b.layouts);
  EXPECT_EQ(a.rack_generator, b.rack_generator);
  EXPECT_EQ(a.started, b.started);
  EXPECT_EQ(a.shot_number, b.shot_number);
  EXPECT_EQ(a.rack, b.rack);
  EXPECT_EQ(a.last_verdict, b.last_verdict);
  EXPECT_EQ(gameJson(a.game), gameJson(b.game));
  EXPECT_EQ(ballsJson(a.balls), ballsJson(b.balls));
  for (std::size_t s = 0; s < 2; ++s) {
    EXPECT_EQ(a.seats[s].player, b.seats[s].player);
    EXPECT_EQ(a.seats[s].token, b.seats[s].token);
    EXPECT_EQ(a.seats[s].client, b.seats[s].client);
    EXPECT_EQ(a.seats[s].last_seq, b.seats[s].last_seq);
    EXPECT_EQ(a.seats[s].fouls, b.seats[s].fouls);
    EXPECT_EQ(a.seats[s].racks_won, b.seats[s].racks_won);
    EXPECT_EQ(a.seats[s].public_key, b.seats[s].public_key);
  }
}

TEST(MatchStoreTest, TheSnapshotOfAShotInMotionIsTheMatchOnceItLands) {
  BrokenMatch b;
  ASSERT_TRUE(b.answer.accepted()) << b.answer.rejection.text;
  ASSERT_TRUE(b.answer.record);
  const server::MatchSnapshot during = b.match->snapshot();
  EXPECT_EQ(b.match->shotNumber(), 0u);  // the match itself has not landed it
  ASSERT_TRUE(finishNow(*b.match));
  const server::MatchSnapshot after = b.match->snapshot();
  expectSameMatch(during, after);
  EXPECT_EQ(after.shot_number, 1u);
  EXPECT_EQ(after.seats[0].last_seq, 1u);
}

TEST(MatchStoreTest, AStoredShotAndMatchReadBackBitForBit) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  BrokenMatch b;
  ASSERT_TRUE(b.answer.record);
  server::MatchSnapshot after = storeBreak(**store, b);
  // A key on a seat goes through the match's own save.
  after.seats[1].public_key = {9, 8, 7};
  (*store)->saveMatches("srv", 1, {after});
  const std::string text = rules::describe(b.answer.record->verdict);

  const auto back = (*store)->match("srv-1");
  ASSERT_TRUE(back);
  expectSameMatch(*back, after);
  const auto shots = (*store)->shots("srv-1");
  ASSERT_EQ(shots.size(), 1u);
  const server::ShotRecord& r = shots[0].record;
  const server::ShotRecord& w = *b.answer.record;
  EXPECT_EQ(r.shot_number, 1u);
  EXPECT_TRUE(r.shoots);
  EXPECT_EQ(commandJson(r.command), commandJson(w.command));
  EXPECT_EQ(r.command.seat_token, kToken0);
  EXPECT_EQ(gameJson(r.state), gameJson(w.state));
  EXPECT_EQ(ballsJson(r.before), ballsJson(w.before));
  EXPECT_EQ(intentJson(r.intent), intentJson(w.intent));
  EXPECT_EQ(eventsJson(r.events), eventsJson(w.events));
  EXPECT_FALSE(r.events.empty());
  EXPECT_EQ(ballsJson(r.after), ballsJson(w.after));
  EXPECT_EQ(verdictJson(r.verdict), verdictJson(w.verdict));
  EXPECT_EQ(shots[0].verdict_text, text);
  // Doubles come back exactly, not just close.
  for (std::size_t i = 0; i < r.events.size(); ++i) {
    EXPECT_EQ(r.events[i].t, w.events[i].t);
    EXPECT_EQ(r.events[i].pos.x(), w.events[i].pos.x());
  }
}

TEST(MatchStoreTest, ASnookerVerdictKeepsItsPenaltyAndMiss) {
  rules::Verdict v;
  v.fouls = {rules::Foul::NoBallHit};
  v.penalty = 7;
  v.miss = true;
  v.next.ball_on = 20;
  v.next.before_miss_free_ball = true;
  v.next.before_miss = {{0, -1.0, 0.1}, {21, 1.4605, 0.0}};
  const rules::Verdict back = verdictFrom(verdictJson(v));
  EXPECT_EQ(back.penalty, 7);
  EXPECT_TRUE(back.miss);
  EXPECT_EQ(back.next.ball_on, 20);
  EXPECT_TRUE(back.next.before_miss_free_ball);
  ASSERT_EQ(back.next.before_miss.size(), 2u);
  EXPECT_EQ(back.next.before_miss[1].x, 1.4605);
  EXPECT_EQ(rules::describe(back), rules::describe(v));
  EXPECT_EQ(verdictJson(back), verdictJson(v));
}

TEST(MatchStoreTest, AResumedMatchGoesOnFromItsStoredShotWithItsPlayersAway) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  BrokenMatch b;
  storeBreak(**store, b);
  ASSERT_TRUE(finishNow(*b.match));

  server::RegistryOptions options;
  options.server_id = "srv";
  server::MatchRegistry registry(options, nineFoot());
  registry.continueAfter((*store)->opened());
  const auto stored = (*store)->match("srv-1");
  ASSERT_TRUE(stored && resumable(*stored));
  server::Match* resumed = registry.adopt(*stored, 5.0);
  ASSERT_NE(resumed, nullptr);
  EXPECT_EQ(registry.adopt(*stored, 5.0), nullptr) << "adopted the same id twice";
  EXPECT_EQ(resumed->shotNumber(), b.match->shotNumber());
  EXPECT_EQ(gameJson(resumed->game()), gameJson(b.match->game()));
  EXPECT_EQ(ballsJson(resumed->balls()), ballsJson(b.match->balls()));
  EXPECT_GT(resumed->revision(), stored->revision);
  for (const auto& seat : resumed->seats()) {
    EXPECT_TRUE(seat.taken());
    EXPECT_FALSE(seat.connected());
  }
  // Away since the resume: the grace period counts from then.
  EXPECT_FALSE(resumed->expireAway(5.0 + 29.0, 30.0));
  protocol::SeatRequest rejoin =
      server::test::seatRequest(protocol::JoinAction::Rejoin, "b", 1, kToken1, 1000);
  rejoin.client = "b2";
  protocol::signSeatRequest(rejoin, server::test::keyOf("b"));
  EXPECT_TRUE(resumed->seatRequest(rejoin).accepted());
  EXPECT_TRUE(resumed->seats()[1].connected());
  // The next match opened takes a new number.
  registry.continueAfter(1);
  EXPECT_EQ(registry.open()->id(), "srv-2");

  // The shooter's stale sequence number stays refused; the next one plays.
  const int shooter = resumed->game().shooter;
  protocol::ShotRequest next = breakShot(1);
  next.seat = shooter;
  next.seat_token = shooter == 0 ? kToken0 : kToken1;
  next.cue.speed = 2.0;
  next.cue_ball_at.reset();
  next.safety = true;
  if (shooter == 0) {
    EXPECT_EQ(resumed->handleShot(server::test::sealed(next), 6.0).rejection.reason,
              server::Reject::StaleSequence);
  }
  next.seq = resumed->seats()[static_cast<std::size_t>(shooter)].last_seq + 1;
  // Signed with the key the stored seat keeps: the resumed match checks it.
  const auto answer = resumed->handleShot(server::test::sealed(next), 6.0);
  EXPECT_NE(answer.rejection.reason, server::Reject::StaleSequence) << answer.rejection.text;
}

TEST(MatchStoreTest, TheAuditPassesAStoredLogAndFindsATamperedOne) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  BrokenMatch b;
  storeBreak(**store, b);
  const Audit sound = auditMatch(**store, "srv-1", *nineFoot());
  EXPECT_TRUE(sound.sound()) << sound.problems.front();
  EXPECT_EQ(sound.shots, 1u);

  // The log says a different story: the cue ball struck nothing.
  (*store)->database().exec(
      "UPDATE shots SET events = (SELECT json_array(json_extract(events, '$[0]')) FROM shots)");
  const Audit tampered = auditMatch(**store, "srv-1", *nineFoot());
  EXPECT_FALSE(tampered.sound());

  // A gap in the shot numbers.
  (*store)->database().exec("UPDATE shots SET shot_number = 2");
  const Audit gap = auditMatch(**store, "srv-1", *nineFoot());
  ASSERT_FALSE(gap.sound());
  EXPECT_NE(gap.problems.front().find("stored after shot 0"), std::string::npos)
      << gap.problems.front();
}

}  // namespace
}  // namespace pool::store::test
