// Every refusal of a shot command, with its reason, in the checking order, changing nothing.
#include <gtest/gtest.h>

#include <limits>

#include "match_fixture.h"
#include "server/match/command_check.h"

namespace pool::server {
namespace {

using namespace test;

/// Sends `command` as it is and expects it refused with `reason`, the match unchanged but for
/// the seat's used-up number after a signed refusal.
void expectRefusedAsSent(Match& m, const protocol::ShotRequest& command, Reject reason) {
  const std::uint64_t revision = m.revision();
  const auto balls = m.balls();
  const std::uint32_t last_seq[2] = {m.seats()[0].last_seq, m.seats()[1].last_seq};
  const CommandAnswer answer = m.handleShot(command, 1.0);
  EXPECT_EQ(answer.rejection.reason, reason)
      << "got " << toString(answer.rejection.reason) << ": " << answer.rejection.text;
  EXPECT_FALSE(answer.rejection.text.empty());
  EXPECT_FALSE(answer.in_motion);
  EXPECT_EQ(m.revision(), revision);
  for (int seat = 0; seat < 2; ++seat) {
    const bool used = protocol::refusedAfterSignature(reason) && command.seat == seat;
    EXPECT_EQ(m.seats()[static_cast<std::size_t>(seat)].last_seq,
              used ? command.seq : last_seq[seat])
        << "seat " << seat;
  }
  EXPECT_EQ(m.balls().size(), balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) EXPECT_EQ(m.balls()[i].pos, balls[i].pos);
}

/// Signs `command` as its seat's player and expects it refused with `reason`.
void expectRefused(Match& m, const protocol::ShotRequest& command, Reject reason) {
  expectRefusedAsSent(m, sealed(command), reason);
}

/// An open table after a break, seat 0 to shoot, the cue ball at the head spot.
void openTable(Match& m, rules::BallInHand in_hand = rules::BallInHand::None) {
  rules::GameState st = m.game();
  st.phase = rules::Phase::Open;
  st.shooter = 0;
  st.ball_in_hand = in_hand;
  ASSERT_TRUE(m.setPosition(st, m.balls()));
}

protocol::ShotRequest calledShot(std::uint32_t seq) {
  protocol::ShotRequest r = breakShot(seq);
  r.called_ball = 1;
  r.called_pocket = "foot_left_corner";
  return r;
}

TEST(CommandCheck, NonFiniteAndOutOfRangeValuesAreMalformed) {
  auto m = seatedMatch();
  auto nan = breakShot();
  nan.cue.speed = std::numeric_limits<double>::quiet_NaN();
  expectRefused(*m, nan, Reject::Malformed);
  auto fast = breakShot();
  fast.cue.speed = 40.0;
  expectRefused(*m, fast, Reject::Malformed);
  auto miscue = breakShot();
  miscue.cue.tip_side = 0.9;
  expectRefused(*m, miscue, Reject::Malformed);
}

TEST(CommandCheck, MalformedComesBeforeEveryOtherCheck) {
  auto m = seatedMatch();
  auto bad = breakShot();
  bad.seat = 1;  // not its turn, wrong token too
  bad.cue.elevation = std::numeric_limits<double>::infinity();
  expectRefused(*m, bad, Reject::Malformed);
}

TEST(CommandCheck, AFreeOrInvalidSeatIsTheWrongSeat) {
  Match lobby("srv-1", "Table 1", runner(), {}, 1);
  ASSERT_TRUE(lobby.takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a")).accepted());
  auto to_free = breakShot();
  to_free.seat = 1;
  expectRefused(lobby, to_free, Reject::WrongSeat);
  auto m = seatedMatch();
  auto invalid = breakShot();
  invalid.seat = 3;
  expectRefused(*m, invalid, Reject::WrongSeat);
}

TEST(CommandCheck, AWrongTokenIsRefused) {
  auto m = seatedMatch();
  auto stolen = breakShot();
  stolen.seat_token = kToken1;
  expectRefused(*m, stolen, Reject::BadToken);
}

TEST(CommandCheck, TheLobbyAndTheOtherSeatAreNotYourTurn) {
  Match lobby("srv-1", "Table 1", runner(), {}, 1);
  ASSERT_TRUE(lobby.takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a")).accepted());
  expectRefused(lobby, breakShot(), Reject::NotYourTurn);
  auto m = seatedMatch();
  auto early = breakShot();
  early.seat = 1;
  early.seat_token = kToken1;
  expectRefused(*m, early, Reject::NotYourTurn);
}

TEST(CommandCheck, AFinishedMatchRefusesWithMatchOver) {
  auto m = seatedMatch();
  m->clientGone("b", 0.0);
  ASSERT_TRUE(m->expireAway(30.0, 30.0));
  expectRefused(*m, breakShot(), Reject::MatchOver);
}

TEST(CommandCheck, CommandsWhileBallsMoveAreRefused) {
  auto m = seatedMatch();
  ASSERT_TRUE(m->handleShot(breakShot(1), 0.0).accepted());
  const CommandAnswer again = m->handleShot(breakShot(2), 0.1);
  EXPECT_EQ(again.rejection.reason, Reject::BallsMoving) << again.rejection.text;
  EXPECT_TRUE(m->inMotion());
  EXPECT_EQ(m->seats()[0].last_seq, 2u);  // signed and refused: used up all the same
}

TEST(CommandCheck, StaleSequenceNumbersAreRefusedAndSignedRefusalsUseThemUp) {
  auto m = seatedMatch();
  expectRefused(*m, breakShot(0), Reject::StaleSequence);  // numbers start above 0
  auto ahead = breakShot(5);
  ahead.cue_ball_at = Eigen::Vector2d(0.3, 0.0);  // in front of the head string
  expectRefused(*m, ahead, Reject::IllegalPlacement);
  // 5 was used up by the signed refusal: it cannot be replayed once it would pass.
  expectRefused(*m, breakShot(5), Reject::StaleSequence);
  auto stolen = breakShot(6);
  stolen.seat_token = kToken1;
  expectRefused(*m, stolen, Reject::BadToken);  // before the signature: 6 stays free
  ASSERT_TRUE(m->handleShot(breakShot(6), 0.0).accepted());
  ASSERT_TRUE(finishNow(*m));
  rules::GameState st = m->game();
  st.shooter = 0;
  st.options.clear();
  st.ball_in_hand = rules::BallInHand::Anywhere;
  ASSERT_TRUE(m->setPosition(st, m->balls()));
  auto replay = breakShot(6);
  replay.called_ball = 1;
  expectRefused(*m, replay, Reject::StaleSequence);
}

TEST(CommandCheck, AnUnsignedCommandIsRefusedBeforeItsNumberIsLookedAt) {
  auto m = seatedMatch();
  protocol::ShotRequest bare = breakShot(1);
  bare.signature.clear();
  expectRefusedAsSent(*m, bare, Reject::Unsigned);
  bare.seq = 0;
  expectRefusedAsSent(*m, bare, Reject::Unsigned);
  bare.seat_token = kToken1;
  expectRefusedAsSent(*m, bare, Reject::BadToken);  // the token is checked first
  EXPECT_TRUE(m->handleShot(breakShot(1), 0.0).accepted());
}

TEST(CommandCheck, ForgedSignaturesAreRefusedAndUseNothingUp) {
  auto m = seatedMatch();
  // Someone who read seat 0's token off the wire signs with their own key, or with seat 1's.
  for (const char* signer : {"eve", "b"}) {
    protocol::ShotRequest forged = breakShot(1);
    protocol::signCommand(forged, keyOf(signer));
    expectRefusedAsSent(*m, forged, Reject::BadSignature);
  }
  // A genuine signature over other fields: a faster shot, another sequence number.
  protocol::ShotRequest faster = breakShot(1);
  faster.cue.speed = 11.0;
  expectRefusedAsSent(*m, faster, Reject::BadSignature);
  protocol::ShotRequest renumbered = breakShot(1);
  renumbered.seq = 2;
  expectRefusedAsSent(*m, renumbered, Reject::BadSignature);
  protocol::ShotRequest cut = breakShot(1);
  cut.signature.resize(63);
  expectRefusedAsSent(*m, cut, Reject::BadSignature);
  protocol::ShotRequest flipped = breakShot(1);
  flipped.signature[10] ^= 0x01;
  expectRefusedAsSent(*m, flipped, Reject::BadSignature);
  // Seat 1's own command signed by seat 0's player: the other seat's key is not its key.
  protocol::ShotRequest other_seat = breakShot(1);
  other_seat.seat = 1;
  other_seat.seat_token = kToken1;
  protocol::signCommand(other_seat, keyOf("a"));
  expectRefusedAsSent(*m, other_seat, Reject::BadSignature);
  EXPECT_TRUE(m->handleShot(breakShot(1), 0.0).accepted());  // 1 is still seat 0's to use
}

TEST(CommandCheck, AReplayedCommandIsStale) {
  auto m = seatedMatch();
  const protocol::ShotRequest shot = breakShot(1);
  ASSERT_TRUE(m->handleShot(shot, 0.0).accepted());
  ASSERT_TRUE(finishNow(*m));
  rules::GameState st = m->game();
  st.shooter = 0;  // seat 0 to shoot again: only the number stands in the way
  st.options.clear();
  ASSERT_TRUE(m->setPosition(st, m->balls()));
  expectRefusedAsSent(*m, shot, Reject::StaleSequence);
}

TEST(CommandCheck, PendingChoicesMustBeAnsweredAndOnlyWithAnOfferedOne) {
  auto m = seatedMatch();
  rules::GameState st = m->game();
  st.phase = rules::Phase::Open;
  st.options = {rules::Choice::PlayOn, rules::Choice::OpponentReBreaks};
  ASSERT_TRUE(m->setPosition(st, m->balls()));
  expectRefused(*m, calledShot(1), Reject::OptionRequired);
  auto respot = calledShot(2);
  respot.option = protocol::ShotOption::RespotEight;
  expectRefused(*m, respot, Reject::OptionNotOffered);
  auto open = seatedMatch();
  openTable(*open);
  auto unasked = calledShot(1);
  unasked.option = protocol::ShotOption::PlayOn;
  expectRefused(*open, unasked, Reject::OptionNotOffered);
}

TEST(CommandCheck, IllegalCueBallPlacementsAreRefused) {
  auto m = seatedMatch();
  auto ahead = breakShot();
  ahead.cue_ball_at = Eigen::Vector2d(0.0, 0.0);  // on the break: behind the head string only
  expectRefused(*m, ahead, Reject::IllegalPlacement);
  auto on_ball = breakShot(2);
  on_ball.cue_ball_at = m->balls()[1].pos.head<2>();
  expectRefused(*m, on_ball, Reject::IllegalPlacement);

  auto open = seatedMatch();
  openTable(*open);  // no ball in hand
  auto placed = calledShot(1);
  placed.cue_ball_at = Eigen::Vector2d(-0.9, 0.2);
  expectRefused(*open, placed, Reject::IllegalPlacement);
}

TEST(CommandCheck, ACueBallInHandOffTheTableMustBePlaced) {
  auto m = seatedMatch();
  rules::GameState st = m->game();
  st.phase = rules::Phase::Open;
  st.ball_in_hand = rules::BallInHand::Anywhere;
  auto balls = m->balls();
  balls[0].state = physics::MotionState::Pocketed;
  ASSERT_TRUE(m->setPosition(st, balls));
  expectRefused(*m, calledShot(1), Reject::IllegalPlacement);
  auto placed = calledShot(2);
  placed.cue_ball_at = Eigen::Vector2d(-0.5, 0.1);
  const CommandAnswer answer = m->handleShot(sealed(placed), 0.0);
  EXPECT_TRUE(answer.accepted()) << answer.rejection.text;
}

TEST(CommandCheck, StandardPlayNeedsALegalCallOrASafety) {
  auto m = seatedMatch();
  openTable(*m);
  expectRefused(*m, breakShot(1), Reject::BadCall);  // no call
  auto eight = calledShot(2);
  eight.called_ball = 8;  // not callable on an open table
  expectRefused(*m, eight, Reject::BadCall);
  auto pocket = calledShot(3);
  pocket.called_pocket = "kitchen";
  expectRefused(*m, pocket, Reject::BadCall);
  auto both = calledShot(4);
  both.safety = true;
  expectRefused(*m, both, Reject::BadCall);
  auto safety = breakShot(5);
  safety.safety = true;
  EXPECT_TRUE(m->handleShot(sealed(safety), 0.0).accepted());
}

TEST(CommandCheck, ARefusedCommandLeavesTheMatchPlayable) {
  auto m = seatedMatch();
  auto bad = breakShot(1);
  bad.seat_token = 99;
  expectRefused(*m, bad, Reject::BadToken);
  EXPECT_TRUE(m->handleShot(breakShot(1), 0.0).accepted());
}

}  // namespace
}  // namespace pool::server
