// The real pool-server over loopback DDS: a break from command to frames, verdict and state.
#include <gtest/gtest.h>

#include <algorithm>

#include "server_fixture.h"

namespace pool::server::test {
namespace {

class ServerFlow : public ServerTest {};

TEST_F(ServerFlow, ALegalBreakIsAcceptedThenFramedThenJudged) {
  start(kBreakFlow, {"--tables", "1", "--fast"});
  TestClient a(kBreakFlow, "a");
  TestClient b(kBreakFlow, "b");
  ASSERT_TRUE(a.waitForServer());
  ASSERT_TRUE(b.waitForServer());
  const Seated s = seat(a, b, "t-1");
  EXPECT_NE(s.token[0], 0u);
  EXPECT_NE(s.token[1], s.token[0]);
  const auto* before = a.waitState(s.match, [](auto& st) { return st.phase == pool_PHASE_BREAK; });
  ASSERT_NE(before, nullptr);
  EXPECT_EQ(before->shooter, 0);
  EXPECT_EQ(before->balls._length, 16u);
  EXPECT_STREQ(before->seats[0].name, "Ada");
  EXPECT_TRUE(before->seats[1].connected);

  a.send(breakShot(s, 0, 1));
  const auto* accepted = a.waitResult(s.match, 0, 1, [](auto& r) { return r.accepted; });
  ASSERT_NE(accepted, nullptr);
  EXPECT_EQ(accepted->shot_number, 1u);
  EXPECT_EQ(accepted->reject_reason, pool_REJECT_NONE);
  const auto* final_result = a.waitFinal(s.match, 0, 1);
  ASSERT_NE(final_result, nullptr);
  ASSERT_GT(final_result->events._length, 1u);
  EXPECT_EQ(final_result->events._buffer[0].type, pool_EVENT_STRIKE);
  EXPECT_EQ(final_result->shot_number, 1u);
  EXPECT_GE(final_result->next_shooter, 0);

  // Frames: best effort, but on loopback they arrive; numbered from 0 at the strike.
  ASSERT_TRUE(b.waitUntil([&] { return b.snapshotCount(s.match) > 0; }, 5s));
  EXPECT_EQ(b.snapshots.front()->shot_number, 1u);
  EXPECT_EQ(b.snapshots.front()->balls._length, 16u);

  // The state at rest after the shot, for both players.
  for (TestClient* c : {&a, &b}) {
    const auto* after = c->waitState(s.match, [](auto& st) { return st.shot_number == 1; });
    ASSERT_NE(after, nullptr);
    EXPECT_GT(after->revision, before->revision);
    EXPECT_NE(after->phase, pool_PHASE_BREAK);
    EXPECT_EQ(after->shooter, final_result->next_shooter);
    EXPECT_EQ(after->balls._length, 16u);
  }
}

TEST_F(ServerFlow, ASpectatorJoiningMidMatchGetsTheStateAtOnceAndLaterShots) {
  start(kSpectator, {"--tables", "1", "--fast"});
  TestClient a(kSpectator, "a");
  TestClient b(kSpectator, "b");
  ASSERT_TRUE(a.waitForServer());
  ASSERT_TRUE(b.waitForServer());
  const Seated s = seat(a, b, "t-1");
  a.send(breakShot(s, 0, 1));
  ASSERT_NE(a.waitFinal(s.match, 0, 1), nullptr);
  const auto* played = a.waitState(s.match, [](auto& st) { return st.shot_number == 1; });
  ASSERT_NE(played, nullptr);

  // A late joiner: the latest state (transient-local) arrives without asking.
  TestClient watcher(kSpectator, "w");
  const auto* seen = watcher.waitState(
      s.match, [](auto& st) { return st.shot_number == 1; }, 5s);
  ASSERT_NE(seen, nullptr);
  // Only the latest state of the match, not its history (the server's free table has its own).
  const auto of_match =
      std::count_if(watcher.states.begin(), watcher.states.end(),
                    [&](const auto& st) { return net::textOf(st->match) == s.match; });
  EXPECT_EQ(of_match, 1) << "only the latest state, not the history";
  ASSERT_EQ(seen->balls._length, played->balls._length);
  for (std::uint32_t i = 0; i < seen->balls._length; ++i) {
    EXPECT_EQ(seen->balls._buffer[i].pos.x, played->balls._buffer[i].pos.x);
    EXPECT_EQ(seen->balls._buffer[i].pos.y, played->balls._buffer[i].pos.y);
  }
  ASSERT_TRUE(watcher.waitForServer());
  const auto joined = watcher.join(pool_JOIN_SPECTATE, s.match);
  ASSERT_TRUE(joined);
  EXPECT_EQ(joined->outcome, pool_JOIN_ACCEPTED);
  EXPECT_EQ(joined->seat_token, 0u);
  EXPECT_TRUE(watcher.waitUntil(
      [&] { return !watcher.infos.empty() && watcher.infos.back()->spectators == 1; }));

  // The next shot reaches the spectator too.
  const int shooter = played->shooter;
  const protocol::ShotRequest next = anyLegalShot(*played, s, shooter == 0 ? 2 : 1);
  (shooter == 0 ? a : b).send(next);
  const auto* answer = watcher.waitAnswer(s.match, shooter, next.seq);
  ASSERT_NE(answer, nullptr);
  EXPECT_TRUE(answer->accepted) << answer->reject_text;
  EXPECT_NE(watcher.waitFinal(s.match, shooter, next.seq), nullptr);
  EXPECT_NE(watcher.waitState(s.match, [](auto& st) { return st.shot_number == 2; }), nullptr);
}

TEST_F(ServerFlow, TwoMatchesInOneServerDoNotCrossTalk) {
  start(kTwoMatches, {"--tables", "2", "--fast"});
  TestClient a(kTwoMatches, "a");
  TestClient b(kTwoMatches, "b");
  TestClient c(kTwoMatches, "c");
  TestClient d(kTwoMatches, "d");
  for (TestClient* x : {&a, &b, &c, &d}) ASSERT_TRUE(x->waitForServer(2));
  const Seated one = seat(a, b, "t-1");
  const Seated two = seat(c, d, "t-2");
  const auto* two_before =
      c.waitState("t-2", [](auto& st) { return st.phase == pool_PHASE_BREAK; });
  ASSERT_NE(two_before, nullptr);
  const std::uint32_t two_revision = two_before->revision;

  // Match 1's token is no good in match 2, although the seat and sequence fit.
  protocol::ShotRequest crossed = breakShot(two, 0, 1);
  crossed.seat_token = one.token[0];
  a.send(crossed);
  const auto* refused = a.waitAnswer("t-2", 0, 1);
  ASSERT_NE(refused, nullptr);
  EXPECT_EQ(refused->reject_reason, pool_REJECT_BAD_TOKEN);

  a.send(breakShot(one, 0, 1));
  ASSERT_NE(a.waitFinal("t-1", 0, 1), nullptr);
  ASSERT_NE(c.waitState("t-1", [](auto& st) { return st.shot_number == 1; }), nullptr);
  EXPECT_EQ(c.snapshotCount("t-2"), 0u);
  EXPECT_EQ(c.latestState("t-2")->revision, two_revision);
  EXPECT_EQ(c.latestState("t-2")->shot_number, 0u);

  // Match 2 plays on its own.
  c.send(breakShot(two, 0, 1));
  const auto* two_final = c.waitFinal("t-2", 0, 1);
  ASSERT_NE(two_final, nullptr);
  EXPECT_EQ(two_final->shot_number, 1u);
}

TEST_F(ServerFlow, MatchesRunSideBySideWhileFramesArePaced) {
  start(kSideBySide, {"--tables", "2"});  // paced at 60 Hz
  TestClient a(kSideBySide, "a");
  TestClient b(kSideBySide, "b");
  TestClient c(kSideBySide, "c");
  TestClient d(kSideBySide, "d");
  for (TestClient* x : {&a, &b, &c, &d}) ASSERT_TRUE(x->waitForServer(2));
  const Seated one = seat(a, b, "t-1");
  const Seated two = seat(c, d, "t-2");
  ASSERT_NE(c.waitState("t-2", [](auto& st) { return st.phase == pool_PHASE_BREAK; }), nullptr);

  a.send(softShot(one, 0, 1));
  ASSERT_NE(a.waitResult("t-1", 0, 1, [](auto& r) { return r.accepted; }), nullptr);
  c.send(softShot(two, 0, 1));
  ASSERT_NE(c.waitResult("t-2", 0, 1, [](auto& r) { return r.accepted; }), nullptr);
  // Match 2 was served while match 1's frames were still going out.
  EXPECT_EQ(c.waitFinal("t-1", 0, 1, 0ms), nullptr) << "match 1 was already over";
  ASSERT_NE(c.waitFinal("t-1", 0, 1), nullptr);
  ASSERT_NE(c.waitFinal("t-2", 0, 1), nullptr);
  EXPECT_GT(c.snapshotCount("t-1"), 30u);
  EXPECT_GT(c.snapshotCount("t-2"), 30u);
}

}  // namespace
}  // namespace pool::server::test
