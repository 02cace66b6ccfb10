// The real pool-server notices vanished players, keeps their seats for the grace, then forfeits.
#include <gtest/gtest.h>

#include "killable_player.h"
#include "server_fixture.h"

namespace pool::server::test {
namespace {

/// When this binary is re-executed as a player, play before gtest starts, then exit.
const bool kIsPlayer = [] {
  const char* domain = std::getenv(kPlayerDomainEnv);
  if (!domain) return false;
  std::_Exit(playUntilKilled(static_cast<std::uint32_t>(std::atoi(domain))));
}();

class ServerPresence : public ServerTest {};

TEST_F(ServerPresence, AKilledPlayerRejoinsWithTheTokenWithinTheGrace) {
  start(kRejoin, {"--tables", "1", "--fast", "--grace", "30"});
  KillablePlayer bob(kRejoin);
  TestClient a(kRejoin, "a");
  ASSERT_TRUE(a.waitForServer());
  const auto ra = a.join(pool_JOIN_SEAT, "t-1", "Ada", 0);
  ASSERT_TRUE(ra && ra->outcome == pool_JOIN_ACCEPTED);
  const auto bob_token = bob.token(20s);
  ASSERT_TRUE(bob_token) << "the player process did not take its seat";
  Seated s;
  s.match = "t-1";
  s.token[0] = ra->seat_token;
  s.token[1] = *bob_token;
  ASSERT_NE(a.waitState(s.match, [](auto& st) { return st.seats[1].connected; }), nullptr);

  // Killed: nothing said on the wire; its JoinRequest writer's lease (5 s) runs out.
  const auto killed = std::chrono::steady_clock::now();
  bob.kill();
  const auto* away = a.waitState(
      s.match, [](auto& st) { return !st.seats[1].connected; }, 20s);
  ASSERT_NE(away, nullptr);
  const auto noticed = std::chrono::steady_clock::now() - killed;
  EXPECT_GT(noticed, net::qos::kPlayerLease / 2) << "away before the lease could run out";
  EXPECT_LT(noticed, net::qos::kPlayerLease + 5s);
  EXPECT_EQ(away->phase, pool_PHASE_BREAK);
  EXPECT_STREQ(away->seats[1].name, "Bob");

  TestClient back(kRejoin, "bob-again");
  ASSERT_TRUE(back.waitForServer());
  const auto bad = back.join(pool_JOIN_REJOIN, s.match, "", -1, s.token[1] + 1);
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->outcome, pool_JOIN_BAD_TOKEN);
  const auto stranger = back.join(pool_JOIN_REJOIN, s.match, "", -1, s.token[1]);
  ASSERT_TRUE(stranger);
  EXPECT_EQ(stranger->outcome, pool_JOIN_BAD_TOKEN) << "the token alone took the seat back";
  const auto kept = bob.key();
  ASSERT_TRUE(kept) << kept.error();
  back.useKey(*kept);  // the player's key, kept across its restart
  const auto rejoined = back.join(pool_JOIN_REJOIN, s.match, "", -1, s.token[1]);
  ASSERT_TRUE(rejoined);
  EXPECT_EQ(rejoined->outcome, pool_JOIN_ACCEPTED);
  EXPECT_EQ(rejoined->seat, 1);
  EXPECT_EQ(rejoined->seat_token, s.token[1]);
  ASSERT_NE(a.waitState(s.match, [](auto& st) { return st.seats[1].connected; }), nullptr);

  // The match goes on with the rejoined player.
  a.send(breakShot(s, 0, 1));
  ASSERT_NE(back.waitFinal(s.match, 0, 1), nullptr);
}

// A client that closes its participant (a clean exit without a leave) vanishes the same way.
TEST_F(ServerPresence, PastTheGraceTheMatchIsForfeitedToTheOpponent) {
  start(kForfeit, {"--tables", "1", "--fast", "--grace", "1"});
  TestClient a(kForfeit, "a");
  auto b = std::make_unique<TestClient>(kForfeit, "b");
  ASSERT_TRUE(a.waitForServer());
  ASSERT_TRUE(b->waitForServer());
  const Seated s = seat(a, *b, "t-1");
  ASSERT_NE(a.waitState(s.match, [](auto& st) { return st.phase == pool_PHASE_BREAK; }), nullptr);
  const auto gone = std::chrono::steady_clock::now();
  b.reset();
  const auto* over = a.waitState(
      s.match, [](auto& st) { return st.phase == pool_PHASE_OVER; }, 8s);
  ASSERT_NE(over, nullptr);
  EXPECT_GE(std::chrono::steady_clock::now() - gone, 900ms);
  EXPECT_EQ(over->winner, 0);
  EXPECT_EQ(over->end, pool_END_FORFEIT);
  EXPECT_EQ(over->seats[0].racks_won, 1);
  EXPECT_EQ(over->shooter, -1);
}

}  // namespace
}  // namespace pool::server::test
