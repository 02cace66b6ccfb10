// A stranger on the domain reads every token and public key off the wire and publishes crafted
// seat requests to the real pool-server: none of them takes, leaves or rejoins anyone's seat.
#include <gtest/gtest.h>

#include "net/wire_fields.h"
#include "protocol/seat_request.h"
#include "server_fixture.h"

namespace pool::server::test {
namespace {

class ServerSeatAttacks : public ServerTest {
 protected:
  /// Seats `a` and `b` at "t-1" once all three clients see the server, and waits for the break;
  /// the state of the break, or null (with a failure).
  const pool_MatchState* seatedAtTheBreak(TestClient& a, TestClient& b, TestClient& eve,
                                          Seated& s) {
    EXPECT_TRUE(a.waitForServer() && b.waitForServer() && eve.waitForServer());
    s = seat(a, b, "t-1");
    const auto* playing =
        a.waitState(s.match, [](auto& st) { return st.phase == pool_PHASE_BREAK; });
    EXPECT_NE(playing, nullptr);
    return playing;
  }
};

/// The token the server gave `victim`'s seat, as any reader of the JoinReply topic sees it.
std::uint64_t tokenReadOffTheWire(TestClient& eve, const std::string& victim) {
  std::uint64_t token = 0;
  eve.waitUntil([&] {
    for (const auto& r : eve.replies) {
      if (net::textOf(r->client) == victim && r->seat_token != 0) token = r->seat_token;
    }
    return token != 0;
  });
  return token;
}

/// A seat request for `victim`'s seat 1 of `match`: its client id, token and public key, numbered
/// far ahead, signed by `signer` (nullptr: unsigned).
protocol::SeatRequest craft(TestClient& eve, pool_JoinAction action, const std::string& match,
                            const TestClient& victim, std::uint64_t token,
                            const protocol::KeyPair* signer) {
  protocol::SeatRequest r = eve.request(action, match, "", 1, token);
  r.client = victim.id();
  r.request += 100000;  // the victim's own request numbers stay its own
  r.seq = 1000000;
  if (signer) protocol::signSeatRequest(r, *signer);
  r.public_key = victim.key().publicKey();  // the victim's key, read off the wire
  return r;
}

pool_JoinOutcome outcomeOf(const std::optional<pool_JoinReply>& reply) {
  EXPECT_TRUE(reply.has_value()) << "no reply";
  if (reply && reply->outcome != pool_JOIN_ACCEPTED) {
    EXPECT_NE(reply->reason[0], '\0');
  }
  return reply ? reply->outcome : pool_JOIN_ACCEPTED;
}

TEST_F(ServerSeatAttacks, StolenTokensAndKeysLeaveRejoinAndRematchNothing) {
  start(kSeatAttacks, {"--tables", "1"});
  TestClient a(kSeatAttacks, "a");
  TestClient b(kSeatAttacks, "b");
  TestClient eve(kSeatAttacks, "eve");
  Seated s;
  const auto* playing = seatedAtTheBreak(a, b, eve, s);
  ASSERT_NE(playing, nullptr);
  const std::uint64_t token = tokenReadOffTheWire(eve, "b");
  ASSERT_EQ(token, s.token[1]) << "the token is public: any reader sees it";
  const std::uint32_t revision = playing->revision;
  const std::size_t states_before = a.stateCount(s.match);

  for (const auto action : {pool_JOIN_LEAVE, pool_JOIN_REJOIN, pool_JOIN_REMATCH}) {
    SCOPED_TRACE(static_cast<int>(action));
    // Signed with Eve's own key: no seat of the match is bound to it.
    protocol::SeatRequest own = eve.request(action, s.match, "", 1, token);
    own.seq = 1000000;
    protocol::signSeatRequest(own, eve.key());
    EXPECT_EQ(outcomeOf(eve.joinAsIs(own)), pool_JOIN_BAD_TOKEN);
    // Bob's client id, token and public key, signed by Eve.
    EXPECT_EQ(outcomeOf(eve.joinAsIs(craft(eve, action, s.match, b, token, &eve.key()))),
              pool_JOIN_BAD_SIGNATURE);
    // The same without a signature.
    EXPECT_EQ(outcomeOf(eve.joinAsIs(craft(eve, action, s.match, b, token, nullptr))),
              pool_JOIN_UNSIGNED);
  }
  a.waitUntil([] { return false; }, 300ms);  // time for any (wrong) state change to arrive
  EXPECT_EQ(a.stateCount(s.match), states_before) << "a refused request changed the match";
  EXPECT_EQ(a.latestState(s.match)->revision, revision);
  EXPECT_TRUE(a.latestState(s.match)->seats[1].connected);
  EXPECT_EQ(a.latestState(s.match)->phase, pool_PHASE_BREAK);

  // Bob's own signed rematch request (refused: the match is not over) uses its number up; the
  // same sample published again by Eve is stale and changes nothing.
  protocol::SeatRequest mine = b.request(pool_JOIN_REMATCH, s.match, "", 1, token);
  mine.seq = b.seq() + 1;
  b.setSeq(mine.seq);
  protocol::signSeatRequest(mine, b.key());
  EXPECT_EQ(outcomeOf(b.joinAsIs(mine)), pool_JOIN_NOT_ALLOWED);
  const auto replayed = eve.joinAsIs(mine);
  EXPECT_EQ(outcomeOf(replayed), pool_JOIN_STALE_SEQUENCE);
  ASSERT_TRUE(replayed.has_value());
  EXPECT_EQ(replayed->last_seq, mine.seq) << "a stale answer names the floor to exceed";

  // A leave Bob signed does leave: the game is forfeited to Ada.
  const auto left = b.join(pool_JOIN_LEAVE, s.match, "", 1, token);
  EXPECT_EQ(outcomeOf(left), pool_JOIN_ACCEPTED);
  const auto* over = a.waitState(s.match, [](auto& st) { return st.phase == pool_PHASE_OVER; });
  ASSERT_NE(over, nullptr);
  EXPECT_EQ(over->winner, 0);
  // Nobody sits down in Bob's name with his public key but without his signature.
  EXPECT_EQ(outcomeOf(eve.joinAsIs(b.request(pool_JOIN_SEAT, s.match, "Bob", 1))),
            pool_JOIN_UNSIGNED);
  // His earlier signed request replayed now: no seat is bound to his key any more.
  EXPECT_EQ(outcomeOf(eve.joinAsIs(mine)), pool_JOIN_BAD_TOKEN);
  EXPECT_FALSE(a.latestState(s.match)->seats[1].name[0] != '\0') << "the seat stays free";
}

/// The concession test's DDS domain, its own (it shared 81 with BotStayTest, and the domain claim
/// refused it the one time both ran at once).
constexpr std::uint32_t kConcedeAttacks = 63;

TEST_F(ServerSeatAttacks, OnlyTheSeatedPlayerConcedesTheirOwnRackAndOnlyOnce) {
  start(kConcedeAttacks, {"--tables", "1", "--race", "2"});
  TestClient a(kConcedeAttacks, "a");
  TestClient b(kConcedeAttacks, "b");
  TestClient eve(kConcedeAttacks, "eve");
  Seated s;
  const auto* playing = seatedAtTheBreak(a, b, eve, s);
  ASSERT_NE(playing, nullptr);
  const std::uint64_t token = tokenReadOffTheWire(eve, "b");
  const std::uint32_t revision = playing->revision;
  const std::size_t states_before = a.stateCount(s.match);

  // Eve, in Bob's name: her own key, his key signed by her, no signature at all.
  protocol::SeatRequest own = eve.request(pool_JOIN_CONCEDE, s.match, "", 1, token);
  own.seq = 1000000;
  protocol::signSeatRequest(own, eve.key());
  EXPECT_EQ(outcomeOf(eve.joinAsIs(own)), pool_JOIN_BAD_TOKEN);
  EXPECT_EQ(outcomeOf(eve.joinAsIs(craft(eve, pool_JOIN_CONCEDE, s.match, b, token, &eve.key()))),
            pool_JOIN_BAD_SIGNATURE);
  EXPECT_EQ(outcomeOf(eve.joinAsIs(craft(eve, pool_JOIN_CONCEDE, s.match, b, token, nullptr))),
            pool_JOIN_UNSIGNED);
  // Ada, signing with her own key, concedes for the other seat: no such seat is bound to her key.
  EXPECT_EQ(outcomeOf(a.join(pool_JOIN_CONCEDE, s.match, "", 1, token)), pool_JOIN_BAD_TOKEN);
  a.waitUntil([] { return false; }, 300ms);  // time for any (wrong) state change to arrive
  EXPECT_EQ(a.stateCount(s.match), states_before) << "a refused concession changed the match";
  EXPECT_EQ(a.latestState(s.match)->revision, revision);
  EXPECT_EQ(a.latestState(s.match)->rack, 1u);

  // Bob concedes his own rack: Ada wins it and the race to 2 goes on with rack 2.
  protocol::SeatRequest mine = b.request(pool_JOIN_CONCEDE, s.match, "", 1, token);
  mine.seq = b.seq() + 1;
  b.setSeq(mine.seq);
  protocol::signSeatRequest(mine, b.key());
  EXPECT_EQ(outcomeOf(b.joinAsIs(mine)), pool_JOIN_ACCEPTED);
  const auto* next = a.waitState(s.match, [](auto& st) { return st.rack == 2; });
  ASSERT_NE(next, nullptr);
  EXPECT_EQ(next->seats[0].racks_won, 1);
  EXPECT_EQ(next->seats[1].racks_won, 0);
  EXPECT_EQ(next->phase, pool_PHASE_BREAK);
  EXPECT_EQ(std::string(net::textOf(next->last_verdict)),
            std::string("seat 1") + protocol::kConcededTheRack + "; rack 2 to break");
  const std::uint32_t after = next->revision;

  // The same sample published again by Eve is stale: rack 2 stays in play, 1-0.
  const auto replayed = eve.joinAsIs(mine);
  EXPECT_EQ(outcomeOf(replayed), pool_JOIN_STALE_SEQUENCE);
  a.waitUntil([] { return false; }, 300ms);
  EXPECT_EQ(a.latestState(s.match)->revision, after);
  EXPECT_EQ(a.latestState(s.match)->seats[0].racks_won, 1);

  // Ada concedes rack 2 (her own, signed): Bob wins it, 1-1, and rack 3 decides the race.
  EXPECT_EQ(outcomeOf(a.join(pool_JOIN_CONCEDE, s.match, "", 0, s.token[0])), pool_JOIN_ACCEPTED);
  const auto* third = a.waitState(s.match, [](auto& st) { return st.rack == 3; });
  ASSERT_NE(third, nullptr);
  EXPECT_EQ(third->seats[1].racks_won, 1);
  // Bob concedes rack 3: the match is Ada's, 2-1; nothing is left to concede.
  EXPECT_EQ(outcomeOf(b.join(pool_JOIN_CONCEDE, s.match, "", 1, token)), pool_JOIN_ACCEPTED);
  const auto* over = a.waitState(s.match, [](auto& st) { return st.phase == pool_PHASE_OVER; });
  ASSERT_NE(over, nullptr);
  EXPECT_EQ(over->winner, 0);
  EXPECT_EQ(over->end, pool_END_FORFEIT);
  EXPECT_EQ(over->seats[0].racks_won, 2);
  EXPECT_EQ(over->seats[1].racks_won, 1);
  EXPECT_EQ(outcomeOf(b.join(pool_JOIN_CONCEDE, s.match, "", 1, token)), pool_JOIN_NOT_ALLOWED);
}

TEST_F(ServerSeatAttacks, AClientOfAnotherProtocolVersionIsToldSo) {
  start(kVersionMismatch, {"--tables", "1"});
  TestClient old(kVersionMismatch, "old");
  ASSERT_TRUE(old.waitForServer());
  const auto reply = old.join(pool_JOIN_SEAT, "t-1", "Ada", -1, 0, protocol::kProtocolVersion - 1);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(reply->outcome, pool_JOIN_VERSION_MISMATCH);
  const std::string ours = "protocol " + std::to_string(protocol::kProtocolVersion);
  EXPECT_NE(std::string(net::textOf(reply->reason)).find(ours), std::string::npos)
      << net::textOf(reply->reason);
  EXPECT_EQ(old.infos.back()->protocol_version, protocol::kProtocolVersion);
}

}  // namespace
}  // namespace pool::server::test
