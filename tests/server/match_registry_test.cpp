// The lobby: unique match ids, joins with their outcomes, presence, commands routed by match id.
#include <gtest/gtest.h>

#include <map>
#include <regex>

#include "match_fixture.h"

namespace pool::server {
namespace {

using namespace test;

RegistryOptions fixedOptions(std::string server_id = "srv") {
  RegistryOptions o;
  o.server_id = std::move(server_id);
  o.seed = 1234;
  o.max_matches = 4;
  return o;
}

// `c` numbered with `signer`'s next sequence number and signed with its key.
JoinCommand signedBy(JoinCommand c, const std::string& signer) {
  static std::map<std::string, std::uint32_t> last;
  c.seq = ++last[signer];
  protocol::signSeatRequest(c, keyOf(signer));
  return c;
}

JoinCommand seatRequest(std::string client, std::string match, std::string name, int seat = -1) {
  JoinCommand c;
  c.client = std::move(client);
  c.protocol_version = RegistryOptions{}.protocol_version;
  c.match = std::move(match);
  c.action = JoinAction::Seat;
  c.seat = seat;
  c.name = std::move(name);
  return signedBy(c, c.client);
}

JoinCommand withToken(std::string client, std::string match, JoinAction action, std::uint64_t token,
                      std::string signer = {}) {
  JoinCommand c = seatRequest(client, std::move(match), "");
  c.action = action;
  c.token = token;
  return signedBy(c, signer.empty() ? client : signer);
}

TEST(MatchRegistry, MatchIdsAreTheServerIdAndACounter) {
  MatchRegistry r(fixedOptions(), nineFoot());
  EXPECT_EQ(r.open()->id(), "srv-1");
  EXPECT_EQ(r.open()->id(), "srv-2");
  EXPECT_EQ(r.find("srv-2")->name(), "Table 2");
  EXPECT_EQ(r.find("srv-3"), nullptr);
}

TEST(MatchRegistry, WithoutAServerIdOneIsDrawnAtRandom) {
  RegistryOptions o = fixedOptions("");
  o.seed = 0;
  MatchRegistry a(o, nineFoot());
  MatchRegistry b(o, nineFoot());
  EXPECT_TRUE(std::regex_match(a.serverId(), std::regex("[0-9a-f]{8}"))) << a.serverId();
  EXPECT_NE(a.serverId(), b.serverId());
  EXPECT_EQ(a.open()->id(), a.serverId() + "-1");
}

TEST(MatchRegistry, SeatsGetDistinctNonZeroTokens) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  const JoinAnswer a = r.join(seatRequest("a", "srv-1", "Ada"));
  const JoinAnswer b = r.join(seatRequest("b", "srv-1", "Zo\xC3\xAB"));  // "Zoë" in UTF-8
  ASSERT_TRUE(a.accepted() && b.accepted()) << a.reason << b.reason;
  EXPECT_EQ(a.match, "srv-1");
  EXPECT_NE(a.token, 0u);
  EXPECT_NE(b.token, 0u);
  EXPECT_NE(a.token, b.token);
  EXPECT_EQ(r.find("srv-1")->phase(), MatchPhase::Break);
  EXPECT_EQ(r.join(seatRequest("c", "srv-1", "Cy")).outcome, JoinOutcome::MatchFull);
}

TEST(MatchRegistry, RefusalsCarryTheirOutcome) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  EXPECT_EQ(r.join(seatRequest("a", "srv-9", "Ada")).outcome, JoinOutcome::NoSuchMatch);
  EXPECT_EQ(r.join(seatRequest("a", "srv-1", "")).outcome, JoinOutcome::BadName);
  EXPECT_EQ(r.join(seatRequest("a", "srv-1", "A\nda")).outcome, JoinOutcome::BadName);
  EXPECT_EQ(r.join(seatRequest("a", "srv-1", "\x1B[2JAda")).outcome, JoinOutcome::BadName);
  EXPECT_EQ(r.join(seatRequest("a", "srv-1", "Zo\xEB")).outcome, JoinOutcome::BadName);  // Latin-1
  EXPECT_EQ(r.join(seatRequest("a", "srv-1", "Ada", 2)).outcome, JoinOutcome::NotAllowed);
  JoinCommand old = seatRequest("a", "srv-1", "Ada");
  old.protocol_version = 0;
  EXPECT_EQ(r.join(old).outcome, JoinOutcome::VersionMismatch);
  EXPECT_EQ(r.join(withToken("a", "srv-1", JoinAction::Rejoin, 5)).outcome, JoinOutcome::BadToken);
  EXPECT_EQ(r.join(withToken("a", "srv-1", JoinAction::Leave, 0)).outcome, JoinOutcome::NotAllowed);
}

TEST(MatchRegistry, NewMatchesAreCreatedOnDemandUntilTheServerIsFull) {
  MatchRegistry r(fixedOptions(), nineFoot());
  for (int i = 1; i <= 4; ++i) {
    const JoinAnswer a = r.join(seatRequest("a", "new", "Ada"));
    ASSERT_TRUE(a.accepted());
    EXPECT_EQ(a.match, "srv-" + std::to_string(i));
  }
  EXPECT_EQ(r.join(seatRequest("a", "new", "Ada")).outcome, JoinOutcome::ServerFull);
}

TEST(MatchRegistry, CreatedMatchesCloseWhenEveryoneLeft) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  const JoinAnswer a = r.join(seatRequest("a", "new", "Ada"));
  ASSERT_TRUE(a.accepted());
  EXPECT_TRUE(r.sweepEmpty().empty());
  ASSERT_TRUE(r.join(withToken("a", a.match, JoinAction::Leave, a.token)).accepted());
  EXPECT_EQ(r.sweepEmpty(), std::vector<std::string>{a.match});
  EXPECT_EQ(r.find(a.match), nullptr);
  EXPECT_NE(r.find("srv-1"), nullptr);                               // opened by the server: stays
  EXPECT_EQ(r.join(seatRequest("b", "new", "Bob")).match, "srv-3");  // ids are never reused
}

TEST(MatchRegistry, AFreeTableIsAlwaysOpenAndFinishedMatchesCloseOnceEmpty) {
  MatchRegistry r(fixedOptions(), nineFoot());  // room for 4 matches
  EXPECT_EQ(r.keepFreeTables(1), 1);
  EXPECT_EQ(r.keepFreeTables(1), 0);
  const JoinAnswer a = r.join(seatRequest("a", "srv-1", "Ada"));
  ASSERT_TRUE(a.accepted());
  EXPECT_EQ(r.keepFreeTables(1), 1) << "Ada's table is no longer free: another opens";
  ASSERT_TRUE(r.join(seatRequest("b", "srv-1", "Bob")).accepted());
  // Bob vanishes and forfeits; nobody comes back to the finished match, which then closes.
  r.clientGone("b", 10.0);
  r.expireAway(41.0, 30.0);
  ASSERT_EQ(r.find("srv-1")->phase(), MatchPhase::Over);
  r.clientGone("a", 50.0);
  EXPECT_TRUE(r.sweepEmpty().empty()) << "closed while Ada may still come back";
  r.expireAway(81.0, 30.0);
  EXPECT_EQ(r.sweepEmpty(), std::vector<std::string>{"srv-1"});
  EXPECT_EQ(r.keepFreeTables(1), 0) << "srv-2 is still free";
  // The cap holds: never more than max_matches open, whatever is asked.
  EXPECT_EQ(r.keepFreeTables(10), 3);
  EXPECT_EQ(r.matches().size(), 4u);
}

TEST(MatchRegistry, AGameBothPlayersLeftIsAbandonedWithoutAResultAndCloses) {
  MatchRegistry r(fixedOptions(), nineFoot());
  ASSERT_TRUE(r.join(seatRequest("a", "new", "Ada")).accepted());
  ASSERT_TRUE(r.join(seatRequest("b", "srv-1", "Bob")).accepted());
  ASSERT_TRUE(r.find("srv-1")->inPlay());
  // Both vanish (a server restarted with nobody coming back looks the same): Ada's grace runs
  // out first, while Bob is away too, so nobody wins by her forfeit.
  r.clientGone("a", 10.0);
  r.clientGone("b", 20.0);
  r.expireAway(41.0, 30.0);
  EXPECT_TRUE(r.find("srv-1")->inPlay()) << "Bob may still come back";
  EXPECT_TRUE(r.sweepEmpty().empty());
  r.expireAway(51.0, 30.0);
  const Match* m = r.find("srv-1");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->game().winner, -1) << "no result for a game nobody finished";
  EXPECT_FALSE(m->seats()[0].taken());
  EXPECT_FALSE(m->seats()[1].taken());
  EXPECT_EQ(r.sweepEmpty(), std::vector<std::string>{"srv-1"});
}

TEST(MatchRegistry, OnePlayerGoneAndTheOtherBackIsAForfeitAsBefore) {
  MatchRegistry r(fixedOptions(), nineFoot());
  ASSERT_TRUE(r.join(seatRequest("a", "new", "Ada")).accepted());
  ASSERT_TRUE(r.join(seatRequest("b", "srv-1", "Bob")).accepted());
  r.clientGone("a", 10.0);
  r.expireAway(41.0, 30.0);
  EXPECT_EQ(r.find("srv-1")->phase(), MatchPhase::Over);
  EXPECT_EQ(r.find("srv-1")->game().winner, 1);
}

TEST(MatchRegistry, SpectatorsJoinAndLeave) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  JoinCommand watch = seatRequest("s", "srv-1", "");
  watch.action = JoinAction::Spectate;
  const JoinAnswer w = r.join(watch);
  ASSERT_TRUE(w.accepted());
  EXPECT_EQ(w.seat, -1);
  EXPECT_EQ(w.token, 0u);
  EXPECT_EQ(r.find("srv-1")->spectators(), 1u);
  ASSERT_TRUE(r.join(withToken("s", "srv-1", JoinAction::Leave, 0)).accepted());
  EXPECT_EQ(r.find("srv-1")->spectators(), 0u);
}

TEST(MatchRegistry, AVanishedPlayerRejoinsWithTheTokenOrForfeitsAfterTheGrace) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  r.open();
  const JoinAnswer a1 = r.join(seatRequest("a", "srv-1", "Ada"));
  ASSERT_TRUE(r.join(seatRequest("b", "srv-1", "Bob")).accepted());
  const JoinAnswer a2 = r.join(seatRequest("a", "srv-2", "Ada"));
  ASSERT_TRUE(r.join(seatRequest("c", "srv-2", "Cy")).accepted());
  r.clientGone("a", 100.0);
  EXPECT_FALSE(r.find("srv-1")->seats()[0].connected());
  EXPECT_FALSE(r.find("srv-2")->seats()[0].connected());
  const JoinCommand stranger = withToken("a-restarted", "srv-1", JoinAction::Rejoin, a1.token);
  EXPECT_EQ(r.join(stranger).outcome, JoinOutcome::BadToken);  // a new key: not the player
  // The key kept by the player who left, in a new process (a new client id).
  const JoinAnswer back =
      r.join(withToken("a-restarted", "srv-1", JoinAction::Rejoin, a1.token, "a"));
  ASSERT_TRUE(back.accepted());
  EXPECT_EQ(back.seat, 0);
  EXPECT_EQ(back.token, a1.token);
  r.expireAway(130.0, 30.0);
  EXPECT_EQ(r.find("srv-1")->phase(), MatchPhase::Break);  // came back in time
  EXPECT_EQ(r.find("srv-2")->phase(), MatchPhase::Over);   // did not
  EXPECT_EQ(r.find("srv-2")->game().winner, 1);
  (void)a2;
}

TEST(MatchRegistry, ASeatNeedsAnEd25519PublicKey) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  JoinCommand keyless = seatRequest("a", "srv-1", "Ada");
  keyless.public_key.clear();
  keyless.signature.clear();
  const JoinAnswer refused = r.join(keyless);
  EXPECT_EQ(refused.outcome, JoinOutcome::NotAllowed);
  EXPECT_NE(refused.reason.find("public_key"), std::string::npos) << refused.reason;
  keyless.public_key.assign(31, 7);
  keyless.signature.assign(64, 7);
  EXPECT_EQ(r.join(keyless).outcome, JoinOutcome::NotAllowed);
  EXPECT_FALSE(r.find("srv-1")->seats()[0].taken());
  const JoinAnswer seated = r.join(seatRequest("a", "srv-1", "Ada"));
  ASSERT_TRUE(seated.accepted());
  EXPECT_EQ(r.find("srv-1")->seats()[0].public_key, publicKeyOf("a"));
}

TEST(MatchRegistry, ASeatRequestMustBeSignedByTheKeyItBindsWithAFreshNumber) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  JoinCommand bare = seatRequest("a", "srv-1", "Ada");
  bare.signature.clear();
  EXPECT_EQ(r.join(bare).outcome, JoinOutcome::Unsigned);
  // Eve binds Ada's public key with her own signature: refused.
  JoinCommand forged = seatRequest("eve", "srv-1", "Ada");
  forged.public_key = publicKeyOf("a");
  EXPECT_EQ(r.join(forged).outcome, JoinOutcome::BadSignature);
  EXPECT_FALSE(r.find("srv-1")->seats()[0].taken());
  EXPECT_EQ(r.matches().size(), 1u);
  // Ada's own request seats her; after she leaves, the same bytes replayed seat nobody.
  const JoinCommand mine = seatRequest("a", "srv-1", "Ada");
  const JoinAnswer seated = r.join(mine);
  ASSERT_TRUE(seated.accepted()) << seated.reason;
  EXPECT_EQ(seated.last_seq, mine.seq);
  ASSERT_TRUE(r.join(withToken("a", "srv-1", JoinAction::Leave, seated.token)).accepted());
  const JoinAnswer replayed = r.join(mine);
  EXPECT_EQ(replayed.outcome, JoinOutcome::StaleSequence);
  EXPECT_GT(replayed.last_seq, mine.seq);
  EXPECT_FALSE(r.find("srv-1")->seats()[0].taken());
  // A "new" table is not opened for a refused request either.
  JoinCommand fresh = mine;
  fresh.match = kNewMatch;
  EXPECT_EQ(r.join(fresh).outcome, JoinOutcome::StaleSequence);
  EXPECT_EQ(r.matches().size(), 1u);
}

TEST(MatchRegistry, ShotsAreRoutedByMatchIdAndUnknownMatchesRefused) {
  MatchRegistry r(fixedOptions(), nineFoot());
  r.open();
  const JoinAnswer a = r.join(seatRequest("a", "srv-1", "Ada"));
  ASSERT_TRUE(r.join(seatRequest("b", "srv-1", "Bob")).accepted());
  protocol::ShotRequest shot = breakShot();
  shot.seat_token = a.token;
  shot.match = "srv-7";
  EXPECT_EQ(r.shoot(shot, 0.0).rejection.reason, Reject::NoSuchMatch);
  shot.match = "srv-1";
  EXPECT_TRUE(r.shoot(sealed(shot), 0.0).accepted());
  EXPECT_EQ(r.nextFrameDue(), 0.0);
}

}  // namespace
}  // namespace pool::server
