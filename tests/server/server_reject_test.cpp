// The real pool-server refuses bad commands with their reasons and the match goes on unchanged.
#include <gtest/gtest.h>

#include <limits>

#include "net/wire_fields.h"
#include "server_fixture.h"

namespace pool::server::test {
namespace {

class ServerRejections : public ServerTest {};

/// Sends `command` from `sender` and returns the reason of the answer to it as `observer` (the
/// same observer throughout a test, so that answers to earlier commands with the same seat and
/// seq are behind its mark: results from the server's one writer arrive in order).
pool_RejectReason answerTo(TestClient& observer, TestClient& sender,
                           const pool_ShotCommand& command) {
  const std::size_t from = observer.mark();
  sender.send(command);
  const auto* answer =
      observer.waitAnswer(std::string(net::textOf(command.match)), command.seat, command.seq, from);
  EXPECT_NE(answer, nullptr) << "no answer to seq " << command.seq;
  if (answer && !answer->accepted) {
    EXPECT_NE(answer->reject_text[0], '\0');
  }
  return answer ? answer->reject_reason : pool_REJECT_NONE;
}

/// The same for `request` signed with the sender's key.
pool_RejectReason answerTo(TestClient& observer, TestClient& sender,
                           protocol::ShotRequest request) {
  protocol::signCommand(request, sender.key());
  return answerTo(observer, sender, *net::toWire(request));
}

TEST_F(ServerRejections, BadCommandsAreRefusedWithTheirReasonsAndChangeNothing) {
  start(kRejections, {"--tables", "1", "--snapshot-hz", "30"});  // paced: balls move for a while
  TestClient a(kRejections, "a");
  TestClient b(kRejections, "b");
  ASSERT_TRUE(a.waitForServer());
  ASSERT_TRUE(b.waitForServer());
  const Seated s = seat(a, b, "t-1");
  const auto* start_state =
      a.waitState(s.match, [](auto& st) { return st.phase == pool_PHASE_BREAK; });
  ASSERT_NE(start_state, nullptr);
  const std::uint32_t revision = start_state->revision;
  const std::size_t states_before = a.stateCount(s.match);

  EXPECT_EQ(answerTo(a, b, breakShot(s, 1, 1)), pool_REJECT_NOT_YOUR_TURN);
  protocol::ShotRequest stolen = breakShot(s, 0, 1);
  stolen.seat_token = s.token[1];
  EXPECT_EQ(answerTo(a, b, stolen), pool_REJECT_BAD_TOKEN);
  protocol::ShotRequest nan = breakShot(s, 0, 1);
  nan.cue.speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(answerTo(a, a, nan), pool_REJECT_MALFORMED);
  protocol::ShotRequest fast = breakShot(s, 0, 1);
  fast.cue.speed = 50.0;
  EXPECT_EQ(answerTo(a, a, fast), pool_REJECT_MALFORMED);
  // (An enum value outside pool.idl's cannot be sent: Cyclone refuses to serialize it. The server's
  // check of it is in match_publish_test.cpp.) Malformed fields that do cross the wire:
  protocol::ShotRequest half_call = breakShot(s, 0, 1);
  half_call.called_pocket = "foot_left_corner";  // a pocket without a ball
  EXPECT_EQ(answerTo(a, a, half_call), pool_REJECT_MALFORMED);
  protocol::ShotRequest no_seat = breakShot(s, 0, 1);
  no_seat.seat = 7;
  EXPECT_EQ(answerTo(a, a, no_seat), pool_REJECT_MALFORMED);
  protocol::ShotRequest ahead = breakShot(s, 0, 1);
  ahead.cue_ball_at = Eigen::Vector2d(0.2, 0.0);
  EXPECT_EQ(answerTo(a, a, ahead), pool_REJECT_ILLEGAL_PLACEMENT);  // signed: 1 is used up
  EXPECT_EQ(answerTo(a, a, breakShot(s, 0, 1)), pool_REJECT_STALE_SEQUENCE);
  // Someone who read seat 0's token off the wire cannot shoot for it, signed or not.
  EXPECT_EQ(answerTo(a, b, *net::toWire(breakShot(s, 0, 2))), pool_REJECT_UNSIGNED);
  EXPECT_EQ(answerTo(a, b, breakShot(s, 0, 2)), pool_REJECT_BAD_SIGNATURE);
  a.waitUntil([] { return false; }, 200ms);  // time for any (wrong) state change to arrive
  EXPECT_EQ(a.stateCount(s.match), states_before) << "a refusal changed the match";
  EXPECT_EQ(a.latestState(s.match)->revision, revision);

  // A legal shot still goes through (the forgeries did not use 2 up), paced to the wall clock.
  const auto sent = std::chrono::steady_clock::now();
  EXPECT_EQ(answerTo(a, a, softShot(s, 0, 2)), pool_REJECT_NONE);
  EXPECT_EQ(answerTo(a, a, breakShot(s, 0, 3)), pool_REJECT_BALLS_MOVING);
  EXPECT_EQ(answerTo(a, b, breakShot(s, 1, 2)), pool_REJECT_NOT_YOUR_TURN);
  const auto* done = a.waitFinal(s.match, 0, 2);
  ASSERT_NE(done, nullptr);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - sent;
  const double motion = done->events._buffer[done->events._length - 1].t;
  EXPECT_GT(motion, 1.0);
  EXPECT_GT(wall.count(), 0.9 * motion) << "frames were not paced";
  EXPECT_GT(a.snapshotCount(s.match), static_cast<std::size_t>(motion * 30 * 0.5));

  // The soft shot was an illegal break: seat 1 chooses to re-rack and break.
  const auto* choose = b.waitState(s.match, [](auto& st) { return st.shot_number == 1; });
  ASSERT_NE(choose, nullptr);
  EXPECT_EQ(choose->shooter, 1);
  ASSERT_GT(choose->options._length, 0u);
  EXPECT_EQ(answerTo(a, b, breakShot(s, 1, 3)), pool_REJECT_OPTION_REQUIRED);
  protocol::ShotRequest respot = breakShot(s, 1, 4);
  respot.option = protocol::ShotOption::RespotEight;
  EXPECT_EQ(answerTo(a, b, respot), pool_REJECT_OPTION_NOT_OFFERED);
  protocol::ShotRequest rebreak = breakShot(s, 1, 5);
  rebreak.option = protocol::ShotOption::ReBreak;
  protocol::signCommand(rebreak, b.key());
  const auto rebreak_bytes = net::toWire(rebreak);
  EXPECT_EQ(answerTo(a, b, *rebreak_bytes), pool_REJECT_NONE);
  ASSERT_NE(b.waitState(s.match,
                        [](auto& st) { return st.phase == pool_PHASE_BREAK && st.shooter == 1; }),
            nullptr);
  // The same bytes again, by anyone: a replay.
  EXPECT_EQ(answerTo(a, a, *rebreak_bytes), pool_REJECT_STALE_SEQUENCE);
  EXPECT_EQ(answerTo(a, b, softShot(s, 1, 6)), pool_REJECT_NONE);
}

TEST_F(ServerRejections, CommandsForAnUnknownMatchAreRefused) {
  start(kJoinRefusals, {"--tables", "1", "--fast"});
  TestClient a(kJoinRefusals, "a");
  ASSERT_TRUE(a.waitForServer());
  Seated nowhere;
  nowhere.match = "t-99";
  EXPECT_EQ(answerTo(a, a, breakShot(nowhere, 0, 1)), pool_REJECT_NO_SUCH_MATCH);

  // Join refusals carry their outcome.
  const auto old = a.join(pool_JOIN_SEAT, "t-1", "Ada", -1, 0, 999);
  ASSERT_TRUE(old);
  EXPECT_EQ(old->outcome, pool_JOIN_VERSION_MISMATCH);
  const auto missing = a.join(pool_JOIN_SEAT, "t-9", "Ada");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->outcome, pool_JOIN_NO_SUCH_MATCH);
  const auto nameless = a.join(pool_JOIN_SEAT, "t-1", "");
  ASSERT_TRUE(nameless);
  EXPECT_EQ(nameless->outcome, pool_JOIN_BAD_NAME);
}

}  // namespace
}  // namespace pool::server::test
