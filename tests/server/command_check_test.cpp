// Every refusal of a shot command, with its reason, in the checking order, changing nothing.
#include <gtest/gtest.h>

#include <limits>

#include "match/command_check.h"
#include "match_fixture.h"

namespace pool::server {
namespace {

using namespace test;

/// Sends `command` and expects it refused with `reason`, the match unchanged.
void expectRefused(Match& m, const net::ShotRequest& command, Reject reason) {
  const std::uint64_t revision = m.revision();
  const auto balls = m.balls();
  const auto last_seq = m.seats()[0].last_seq;
  const CommandAnswer answer = m.handleShot(command, 1.0);
  EXPECT_EQ(answer.rejection.reason, reason)
      << "got " << toString(answer.rejection.reason) << ": " << answer.rejection.text;
  EXPECT_FALSE(answer.rejection.text.empty());
  EXPECT_FALSE(answer.in_motion);
  EXPECT_EQ(m.revision(), revision);
  EXPECT_EQ(m.seats()[0].last_seq, last_seq);
  EXPECT_EQ(m.balls().size(), balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) EXPECT_EQ(m.balls()[i].pos, balls[i].pos);
}

/// An open table after a break, seat 0 to shoot, the cue ball at the head spot.
void openTable(Match& m, rules::BallInHand in_hand = rules::BallInHand::None) {
  rules::GameState st = m.game();
  st.phase = rules::Phase::Open;
  st.shooter = 0;
  st.ball_in_hand = in_hand;
  ASSERT_TRUE(m.setPosition(st, m.balls()));
}

net::ShotRequest calledShot(std::uint32_t seq) {
  net::ShotRequest r = breakShot(seq);
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
  ASSERT_TRUE(lobby.takeSeat(0, "Ada", "a", kToken0).accepted());
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
  ASSERT_TRUE(lobby.takeSeat(0, "Ada", "a", kToken0).accepted());
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
  EXPECT_EQ(m->seats()[0].last_seq, 1u);
}

TEST(CommandCheck, StaleSequenceNumbersAreRefusedAndRefusalsDoNotUseThemUp) {
  auto m = seatedMatch();
  expectRefused(*m, breakShot(0), Reject::StaleSequence);  // numbers start above 0
  auto ahead = breakShot(5);
  ahead.cue_ball_at = Eigen::Vector2d(0.3, 0.0);  // in front of the head string
  expectRefused(*m, ahead, Reject::IllegalPlacement);
  ASSERT_TRUE(m->handleShot(breakShot(5), 0.0).accepted());  // 5 was not used up
  ASSERT_TRUE(finishNow(*m));
  rules::GameState st = m->game();
  st.shooter = 0;
  st.options.clear();
  st.ball_in_hand = rules::BallInHand::Anywhere;
  ASSERT_TRUE(m->setPosition(st, m->balls()));
  auto replay = breakShot(5);
  replay.called_ball = 1;
  expectRefused(*m, replay, Reject::StaleSequence);
}

TEST(CommandCheck, PendingChoicesMustBeAnsweredAndOnlyWithAnOfferedOne) {
  auto m = seatedMatch();
  rules::GameState st = m->game();
  st.phase = rules::Phase::Open;
  st.options = {rules::Choice::PlayOn, rules::Choice::OpponentReBreaks};
  ASSERT_TRUE(m->setPosition(st, m->balls()));
  expectRefused(*m, calledShot(1), Reject::OptionRequired);
  auto respot = calledShot(1);
  respot.option = net::ShotOption::RespotEight;
  expectRefused(*m, respot, Reject::OptionNotOffered);
  auto open = seatedMatch();
  openTable(*open);
  auto unasked = calledShot(1);
  unasked.option = net::ShotOption::PlayOn;
  expectRefused(*open, unasked, Reject::OptionNotOffered);
}

TEST(CommandCheck, IllegalCueBallPlacementsAreRefused) {
  auto m = seatedMatch();
  auto ahead = breakShot();
  ahead.cue_ball_at = Eigen::Vector2d(0.0, 0.0);  // on the break: behind the head string only
  expectRefused(*m, ahead, Reject::IllegalPlacement);
  auto on_ball = breakShot();
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
  auto placed = calledShot(1);
  placed.cue_ball_at = Eigen::Vector2d(-0.5, 0.1);
  const CommandAnswer answer = m->handleShot(placed, 0.0);
  EXPECT_TRUE(answer.accepted()) << answer.rejection.text;
}

TEST(CommandCheck, StandardPlayNeedsALegalCallOrASafety) {
  auto m = seatedMatch();
  openTable(*m);
  expectRefused(*m, breakShot(1), Reject::BadCall);  // no call
  auto eight = calledShot(1);
  eight.called_ball = 8;  // not callable on an open table
  expectRefused(*m, eight, Reject::BadCall);
  auto pocket = calledShot(1);
  pocket.called_pocket = "kitchen";
  expectRefused(*m, pocket, Reject::BadCall);
  auto both = calledShot(1);
  both.safety = true;
  expectRefused(*m, both, Reject::BadCall);
  auto safety = breakShot(1);
  safety.safety = true;
  EXPECT_TRUE(m->handleShot(safety, 0.0).accepted());
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
