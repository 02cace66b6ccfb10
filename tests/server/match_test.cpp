// A match's seats, its rack, and an accepted break from command to committed verdict.
#include <gtest/gtest.h>

#include "match_fixture.h"
#include "rules/table_context.h"

namespace pool::server {
namespace {

using namespace test;

TEST(MatchSeats, TwoPlayersStartARackWithTheCueBallBehindTheHeadString) {
  Match m("srv-1", "Table 1", runner(), {}, 7);
  EXPECT_EQ(m.phase(), MatchPhase::Lobby);
  const JoinAnswer a = m.takeSeat(-1, "Ada", "a", kToken0, publicKeyOf("a"));
  ASSERT_TRUE(a.accepted());
  EXPECT_EQ(a.seat, 0);
  EXPECT_EQ(a.token, kToken0);
  EXPECT_EQ(m.phase(), MatchPhase::Lobby);
  const JoinAnswer b = m.takeSeat(-1, "Bob", "b", kToken1, publicKeyOf("b"));
  ASSERT_TRUE(b.accepted());
  EXPECT_EQ(b.seat, 1);
  EXPECT_EQ(m.phase(), MatchPhase::Break);
  EXPECT_EQ(m.game().shooter, 0);
  EXPECT_EQ(m.rack(), 1u);
  ASSERT_EQ(m.balls().size(), 16u);
  EXPECT_LT(m.balls()[0].pos.x(), m.table().context.spots.head_string_x);
}

TEST(MatchSeats, TakenSeatsAndFullMatchesAreRefused) {
  auto m = seatedMatch();
  EXPECT_EQ(m->takeSeat(0, "Cy", "c", 0x3333, publicKeyOf("c")).outcome, JoinOutcome::SeatTaken);
  EXPECT_EQ(m->takeSeat(-1, "Cy", "c", 0x3333, publicKeyOf("c")).outcome, JoinOutcome::MatchFull);
}

TEST(MatchSeats, ARepeatedRequestGetsTheSameSeatAndToken) {
  auto m = seatedMatch();
  const std::uint64_t before = m->revision();
  const JoinAnswer again = m->takeSeat(-1, "Ada", "a", 0x9999, publicKeyOf("a"));
  ASSERT_TRUE(again.accepted());
  EXPECT_EQ(again.seat, 0);
  EXPECT_EQ(again.token, kToken0);
  EXPECT_EQ(m->revision(), before);
}

TEST(MatchSeats, SpectatorsAreCountedOnce) {
  auto m = seatedMatch();
  m->addSpectator("s1");
  m->addSpectator("s1");
  m->addSpectator("s2");
  EXPECT_EQ(m->spectators(), 2u);
  EXPECT_TRUE(m->removeSpectator("s1"));
  EXPECT_FALSE(m->removeSpectator("s1"));
  m->clientGone("s2", 1.0);
  EXPECT_EQ(m->spectators(), 0u);
}

TEST(MatchShot, AnAcceptedBreakPublishesPacedFramesThenCommits) {
  auto m = seatedMatch();
  const double start = 100.0;
  const CommandAnswer answer = m->handleShot(breakShot(), start);
  ASSERT_TRUE(answer.accepted()) << answer.rejection.text;
  EXPECT_TRUE(answer.in_motion);
  EXPECT_EQ(answer.shot_number, 1u);
  EXPECT_TRUE(m->inMotion());
  EXPECT_EQ(m->shotNumber(), 0u);  // committed only when the motion is out

  // Frames at exactly k / 60 s of simulated time, each handed out once its time has come.
  auto first = m->takeDueFrames(start).frames;
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].t, 0.0);
  EXPECT_EQ(first[0].balls.size(), 16u);
  EXPECT_EQ(m->nextFrameDue(), start + 1.0 / 60.0);
  const DueFrames due = m->takeDueFrames(start + 0.5);
  EXPECT_EQ(due.first, 1u);
  EXPECT_EQ(due.shot_number, 1u);
  auto next = due.frames;
  ASSERT_EQ(next.size(), 30u);
  EXPECT_DOUBLE_EQ(next.back().t, 30.0 / 60.0);
  EXPECT_FALSE(m->finishShot());

  const auto report = finishNow(*m);
  ASSERT_TRUE(report);
  EXPECT_FALSE(m->inMotion());
  EXPECT_EQ(report->shot_number, 1u);
  EXPECT_EQ(report->seat, 0);
  ASSERT_FALSE(report->events.empty());
  EXPECT_EQ(report->events.front().type, physics::EventType::Strike);
  EXPECT_EQ(m->shotNumber(), 1u);
  EXPECT_NE(m->phase(), MatchPhase::Break);
  EXPECT_EQ(m->game().shooter, report->verdict.next.shooter);
  EXPECT_EQ(m->seats()[0].last_seq, 1u);
  EXPECT_FALSE(m->lastVerdict().empty());
  for (const auto& b : m->balls()) {
    EXPECT_LT(b.vel.norm(), 1e-6) << "ball " << b.id << " still moves";
  }
}

TEST(MatchShot, UnpacedShotsHandOutEveryFrameAtOnceAndEndAtRest) {
  MatchOptions fast;
  fast.unpaced = true;
  auto m = seatedMatch(fast);
  ASSERT_TRUE(m->handleShot(breakShot(), 5.0).accepted());
  const auto frames = m->takeDueFrames(5.0).frames;
  ASSERT_GT(frames.size(), 60u);
  EXPECT_FALSE(m->nextFrameDue());
  const auto last_frame = frames.back();
  const auto report = m->finishShot();
  ASSERT_TRUE(report);
  // The last frame is the table at rest (before any re-spot the verdict asked for).
  ASSERT_EQ(last_frame.balls.size(), m->balls().size());
  if (report->verdict.respots.empty() && !report->verdict.rerack) {
    for (std::size_t i = 0; i < last_frame.balls.size(); ++i) {
      EXPECT_EQ(last_frame.balls[i].pos, m->balls()[i].pos) << "ball " << i;
    }
  }
}

TEST(MatchShot, TheSameBreakOnTheSameRackGivesTheSameOutcome) {
  MatchOptions fast;
  fast.unpaced = true;
  auto a = seatedMatch(fast);
  auto b = seatedMatch(fast);
  ASSERT_TRUE(a->handleShot(breakShot(), 0.0).accepted());
  ASSERT_TRUE(b->handleShot(breakShot(), 0.0).accepted());
  const auto ra = finishNow(*a);
  const auto rb = finishNow(*b);
  ASSERT_TRUE(ra && rb);
  ASSERT_EQ(ra->events.size(), rb->events.size());
  for (std::size_t i = 0; i < a->balls().size(); ++i) {
    EXPECT_EQ(a->balls()[i].pos, b->balls()[i].pos);
  }
}

TEST(MatchShot, AChoiceWithoutAShotIsDoneAtOnce) {
  auto m = seatedMatch();
  rules::GameState st = m->game();
  st.phase = rules::Phase::Open;
  st.shooter = 1;
  st.options = {rules::Choice::PlayOn, rules::Choice::ReBreak};
  ASSERT_TRUE(m->setPosition(st, m->balls()));
  protocol::ShotRequest r = breakShot();
  r.seat = 1;
  r.seat_token = kToken1;
  r.option = protocol::ShotOption::ReBreak;
  r.cue.speed = 0.0;  // no shot: the cue values are not looked at
  const CommandAnswer answer = m->handleShot(sealed(r), 1.0);
  ASSERT_TRUE(answer.accepted()) << answer.rejection.text;
  EXPECT_FALSE(answer.in_motion);
  ASSERT_TRUE(answer.done);
  EXPECT_TRUE(answer.done->verdict.rerack);
  EXPECT_EQ(m->phase(), MatchPhase::Break);
  EXPECT_EQ(m->game().breaker, 1);
  EXPECT_EQ(m->game().shooter, 1);
  EXPECT_EQ(m->seats()[1].last_seq, 1u);
}

TEST(MatchPresence, ALeaverInPlayForfeitsToTheOpponent) {
  auto m = seatedMatch();
  const JoinAnswer left = m->seatRequest(seatRequest(JoinAction::Leave, "b", 1, kToken1, 1));
  ASSERT_TRUE(left.accepted()) << left.reason;
  EXPECT_EQ(left.last_seq, 1u);
  EXPECT_EQ(m->phase(), MatchPhase::Over);
  EXPECT_EQ(m->game().winner, 0);
  EXPECT_EQ(m->game().end, rules::GameEnd::Forfeit);
  EXPECT_EQ(m->seats()[0].racks_won, 1);
  EXPECT_FALSE(m->seats()[1].taken());
}

TEST(MatchPresence, AnAwayPlayerKeepsTheSeatForTheGracePeriodAndMayRejoin) {
  auto m = seatedMatch();
  m->clientGone("b", 10.0);
  EXPECT_FALSE(m->seats()[1].connected());
  EXPECT_FALSE(m->expireAway(39.9, 30.0));
  EXPECT_EQ(m->phase(), MatchPhase::Break);
  protocol::SeatRequest rejoin = seatRequest(JoinAction::Rejoin, "b", -1, kToken1, 1);
  rejoin.client = "b2";  // a restarted process: a new client id, the same key
  protocol::signSeatRequest(rejoin, keyOf("b"));
  const JoinAnswer back = m->seatRequest(rejoin);
  ASSERT_TRUE(back.accepted()) << back.reason;
  EXPECT_EQ(back.seat, 1);
  EXPECT_EQ(m->seats()[1].client, "b2");
  EXPECT_TRUE(m->seats()[1].connected());
  EXPECT_FALSE(m->expireAway(100.0, 30.0));
  EXPECT_EQ(m->seatRequest(seatRequest(JoinAction::Rejoin, "x", -1, 0x7777, 1)).outcome,
            JoinOutcome::BadToken);
}

// A stranger on the LAN reads every token and public key off the wire; none of that lets it act
// for a seat: each attempt is refused with its reason and changes nothing.
TEST(MatchPresence, ReadingTokenAndKeyOffTheWireTakesNothing) {
  auto m = seatedMatch();
  m->clientGone("b", 10.0);
  const std::uint64_t revision = m->revision();
  const auto refused = [&](const protocol::SeatRequest& r, JoinOutcome outcome, const char* what) {
    const JoinAnswer a = m->seatRequest(r);
    EXPECT_EQ(a.outcome, outcome) << what << ": " << toString(a.outcome) << " " << a.reason;
  };
  for (const auto action : {JoinAction::Rejoin, JoinAction::Leave, JoinAction::Rematch}) {
    // Eve's own key: no seat of the match is bound to it.
    refused(seatRequest(action, "eve", 1, kToken1, 5), JoinOutcome::BadToken, "own key");
    // Bob's public key and token, signed by Eve.
    refused(seatRequest(action, "b", 1, kToken1, 5, "eve"), JoinOutcome::BadSignature, "forged");
    // Bob's public key and token, no signature.
    refused(unsignedCopy(seatRequest(action, "b", 1, kToken1, 5)), JoinOutcome::Unsigned,
            "unsigned");
    // Signed by Bob for another holding of the seat (another token).
    refused(seatRequest(action, "b", 1, 0x9999, 5), JoinOutcome::BadToken, "other holding");
    // Signed by Ada for her seat, sent as Bob's.
    refused(seatRequest(action, "a", 1, kToken1, 5), JoinOutcome::BadToken, "other seat");
  }
  EXPECT_EQ(m->revision(), revision);
  EXPECT_FALSE(m->seats()[1].connected());
  EXPECT_EQ(m->seats()[1].client, "b");
  EXPECT_EQ(m->phase(), MatchPhase::Break);
  // Bob's own signed request is taken; the same bytes again are stale and change nothing.
  const protocol::SeatRequest mine = seatRequest(JoinAction::Rejoin, "b", 1, kToken1, 3);
  ASSERT_TRUE(m->seatRequest(mine).accepted());
  const std::uint64_t after = m->revision();
  const JoinAnswer replayed = m->seatRequest(mine);
  EXPECT_EQ(replayed.outcome, JoinOutcome::StaleSequence);
  EXPECT_EQ(replayed.last_seq, 3u);
  EXPECT_EQ(m->revision(), after);
  // A leave replayed from an earlier request of his is stale too: the game goes on.
  EXPECT_EQ(m->seatRequest(seatRequest(JoinAction::Leave, "b", 1, kToken1, 2)).outcome,
            JoinOutcome::StaleSequence);
  EXPECT_EQ(m->phase(), MatchPhase::Break);
}

TEST(MatchPresence, TimeTheServerWasNotRunningCountsAgainstNobody) {
  auto m = seatedMatch();
  m->clientGone("b", 10.0);
  m->pause(25.0);  // stopped from 12 s to 37 s, say
  EXPECT_FALSE(m->expireAway(64.9, 30.0)) << "the 25 s the server was stopped counted";
  EXPECT_EQ(m->phase(), MatchPhase::Break);
  EXPECT_TRUE(m->expireAway(65.0, 30.0));
  EXPECT_EQ(m->phase(), MatchPhase::Over);
}

TEST(MatchPresence, FramesDueDuringAStallAreNotSentInOneBurst) {
  auto m = seatedMatch();
  ASSERT_TRUE(m->handleShot(breakShot(), 0.0).accepted());
  const auto first = m->takeDueFrames(0.5);
  ASSERT_FALSE(first.frames.empty());
  m->pause(20.0);
  // Half a second of frames after the resume, not twenty.
  const auto after = m->takeDueFrames(21.0);
  EXPECT_LE(after.frames.size(), first.frames.size() + 2);
  ASSERT_TRUE(m->nextFrameDue());
  EXPECT_GT(*m->nextFrameDue(), 21.0);
}

TEST(MatchPresence, PastTheGracePeriodTheGameIsForfeited) {
  auto m = seatedMatch();
  m->clientGone("a", 10.0);
  EXPECT_TRUE(m->expireAway(40.0, 30.0));
  EXPECT_EQ(m->phase(), MatchPhase::Over);
  EXPECT_EQ(m->game().winner, 1);
  EXPECT_EQ(m->game().end, rules::GameEnd::Forfeit);
}

TEST(MatchPresence, AForfeitDuringAShotWaitsForItsEnd) {
  auto m = seatedMatch();
  ASSERT_TRUE(m->handleShot(breakShot(), 0.0).accepted());
  m->clientGone("b", 0.0);
  EXPECT_TRUE(m->expireAway(31.0, 30.0));
  EXPECT_TRUE(m->inMotion());
  ASSERT_TRUE(finishNow(*m));
  if (m->phase() != MatchPhase::Over || m->game().end != rules::GameEnd::Forfeit) {
    ADD_FAILURE() << "not forfeited after the shot: " << toString(m->phase());
  }
  EXPECT_EQ(m->game().winner, 0);
}

TEST(MatchRematch, BothPlayersMustAskAndTheOtherSeatBreaks) {
  auto m = seatedMatch();
  EXPECT_EQ(m->seatRequest(seatRequest(JoinAction::Rematch, "a", 0, kToken0, 1)).outcome,
            JoinOutcome::NotAllowed);  // not over yet
  m->clientGone("b", 0.0);
  m->expireAway(30.0, 30.0);
  ASSERT_EQ(m->phase(), MatchPhase::Over);
  ASSERT_TRUE(m->seatRequest(seatRequest(JoinAction::Rejoin, "b", 1, kToken1, 1)).accepted());
  ASSERT_TRUE(m->seatRequest(seatRequest(JoinAction::Rematch, "a", 0, kToken0, 2)).accepted());
  EXPECT_EQ(m->phase(), MatchPhase::Over);
  ASSERT_TRUE(m->seatRequest(seatRequest(JoinAction::Rematch, "b", 1, kToken1, 2)).accepted());
  EXPECT_EQ(m->phase(), MatchPhase::Break);
  EXPECT_EQ(m->rack(), 2u);
  EXPECT_EQ(m->game().breaker, 1);
  // A rematch is a new race: the score starts again.
  EXPECT_EQ(m->seats()[0].racks_won, 0);
  EXPECT_EQ(m->seats()[1].racks_won, 0);
}

TEST(MatchConcede, NotWhileAShotIsInMotionThenTheOpponentWinsTheRack) {
  auto m = seatedMatch();
  ASSERT_TRUE(m->handleShot(breakShot(), 0.0).accepted());
  ASSERT_TRUE(m->inMotion());
  const JoinAnswer moving = m->seatRequest(seatRequest(JoinAction::Concede, "b", 1, kToken1, 1));
  EXPECT_EQ(moving.outcome, JoinOutcome::NotAllowed);
  EXPECT_EQ(moving.reason, "a shot is in motion");
  ASSERT_TRUE(finishNow(*m));
  ASSERT_TRUE(m->inPlay());
  const std::uint32_t shots = m->shotNumber();
  // The same seat's next number: the refused one was used up.
  EXPECT_EQ(m->seatRequest(seatRequest(JoinAction::Concede, "b", 1, kToken1, 1)).outcome,
            JoinOutcome::StaleSequence);
  ASSERT_TRUE(m->seatRequest(seatRequest(JoinAction::Concede, "b", 1, kToken1, 2)).accepted());
  // A race to 1: that rack was the match.
  EXPECT_EQ(m->phase(), MatchPhase::Over);
  EXPECT_EQ(m->game().winner, 0);
  EXPECT_EQ(m->game().end, rules::GameEnd::Forfeit);
  EXPECT_EQ(m->seats()[0].racks_won, 1);
  EXPECT_EQ(m->seats()[1].racks_won, 0);
  EXPECT_EQ(m->shotNumber(), shots) << "a concession is no shot";
  EXPECT_EQ(m->lastVerdict(), "seat 1 conceded the rack: seat 0 won the match");
  EXPECT_EQ(m->seatRequest(seatRequest(JoinAction::Concede, "a", 0, kToken0, 2)).outcome,
            JoinOutcome::NotAllowed)
      << "nothing left to concede";
}

}  // namespace
}  // namespace pool::server
