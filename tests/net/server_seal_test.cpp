// The server's signature of published samples: it covers every field (whatever the type), binds
// the kind, fails for another key or no signature, and names another protocol version.
#include <gtest/gtest.h>

#include "net/message_convert.h"
#include "net/server_seal.h"
#include "net/wire_fields.h"
#include "protocol/server_signature.h"

namespace pool::net::test {
namespace {

Sample<pool_MatchState> state() {
  protocol::MatchView view;
  view.match = "lab-7";
  view.revision = 12;
  view.phase = protocol::MatchPhase::Open;
  view.seats[0].name = "Ada";
  view.seats[1].name = "Bob";
  view.seats[1].last_seq = 9;
  view.shooter = 1;
  view.shot_number = 4;
  physics::Ball ball;
  ball.id = 3;
  ball.pos = physics::Vec3(0.25, -0.1, 0.028575);
  view.balls = {ball};
  return toWire(view);
}

TEST(ServerSealTest, ASealedSampleVerifiesAndNamesItsServer) {
  const auto key = protocol::generateKeyPair();
  auto s = state();
  seal(*s, key);
  const auto sealed = sealedOf(*s);
  EXPECT_EQ(sealed.server, "lab");
  EXPECT_EQ(sealed.match, "lab-7");
  EXPECT_EQ(sealed.kind, protocol::PublishedKind::MatchState);
  EXPECT_TRUE(std::equal(sealed.server_key.begin(), sealed.server_key.end(), key.public_key.begin(),
                         key.public_key.end()));
  EXPECT_TRUE(protocol::checkSeal(sealed).ok());
}

TEST(ServerSealTest, EveryFieldIsCoveredTheLastOnesToo) {
  const auto key = protocol::generateKeyPair();
  // Each change is made after sealing; the signature must then fail.
  const std::vector<std::pair<const char*, std::function<void(pool_MatchState&)>>> changes{
      {"revision", [](pool_MatchState& s) { s.revision = 0xfffffff0u; }},
      {"phase", [](pool_MatchState& s) { s.phase = pool_PHASE_OVER; }},
      {"a seat's name", [](pool_MatchState& s) { setText(s.seats[1].name, "Mallory"); }},
      {"a ball", [](pool_MatchState& s) { s.balls._buffer[0].pos.x = 0.3; }},
      {"seat_seq (after the balls)", [](pool_MatchState& s) { s.seat_seq[1] = 10; }},
      {"the key carried", [](pool_MatchState& s) { s.server_key._buffer[0] ^= 1; }},
  };
  for (const auto& [what, change] : changes) {
    auto s = state();
    seal(*s, key);
    change(*s);
    EXPECT_FALSE(protocol::checkSeal(sealedOf(*s)).ok()) << what << " is not covered";
  }
}

TEST(ServerSealTest, UnsignedAnotherKeysAndAnotherKindsSignaturesFail) {
  const auto key = protocol::generateKeyPair();
  const auto other = protocol::generateKeyPair();
  auto s = state();
  setBytes(s->server_key, key.public_key, protocol::kPublicKeyBytes);
  EXPECT_NE(protocol::checkSeal(sealedOf(*s)).error().find("unsigned"), std::string::npos);

  // Signed by another key while carrying ours.
  seal(*s, other);
  setBytes(s->server_key, key.public_key, protocol::kPublicKeyBytes);
  EXPECT_NE(protocol::checkSeal(sealedOf(*s)).error().find("does not verify"), std::string::npos);

  // A state's signature read as a frame's.
  seal(*s, key);
  auto sealed = sealedOf(*s);
  EXPECT_TRUE(protocol::checkSeal(sealed).ok());
  sealed.kind = protocol::PublishedKind::TableSnapshot;
  EXPECT_FALSE(protocol::checkSeal(sealed).ok());
}

TEST(ServerSealTest, EachPublishedTypeIsSealedAndAnotherVersionIsNamed) {
  const auto key = protocol::generateKeyPair();
  protocol::LobbyEntry entry;
  entry.match = "lab-1";
  entry.server = "lab";
  entry.protocol_version = protocol::kProtocolVersion;
  auto info = toWire(entry);
  seal(*info, key);
  EXPECT_TRUE(protocol::checkSeal(sealedOf(*info)).ok());
  info->protocol_version = 3;
  seal(*info, key);
  EXPECT_NE(protocol::checkSeal(sealedOf(*info)).error().find("speaks protocol 3"),
            std::string::npos);

  protocol::JoinAnswer answer;
  answer.client = "c";
  answer.server = "lab";
  answer.match = "lab-1";
  auto reply = toWire(answer);
  seal(*reply, key);
  EXPECT_EQ(sealedOf(*reply).server, "lab");
  EXPECT_TRUE(protocol::checkSeal(sealedOf(*reply)).ok());

  protocol::ShotReport report;
  report.match = "lab-1";
  report.verdict_text = "ok";
  auto result = toWire(report);
  seal(*result, key);
  EXPECT_TRUE(protocol::checkSeal(sealedOf(*result)).ok());
  result->game_over = true;
  EXPECT_FALSE(protocol::checkSeal(sealedOf(*result)).ok());

  protocol::TableFrame frame;
  frame.match = "lab-1";
  frame.shot_number = 2;
  auto snapshot = toWire(frame);
  seal(*snapshot, key);
  EXPECT_TRUE(protocol::checkSeal(sealedOf(*snapshot)).ok());
  snapshot->shot_number = 0xffffffffu;
  EXPECT_FALSE(protocol::checkSeal(sealedOf(*snapshot)).ok());
}

TEST(ServerSealTest, FingerprintsAndServerIds) {
  const auto a = protocol::generateKeyPair();
  const auto b = protocol::generateKeyPair();
  const std::string fa = protocol::fingerprint(a.public_key);
  EXPECT_EQ(fa.size(), 39u);
  EXPECT_EQ(fa, protocol::fingerprint(a.public_key));
  EXPECT_NE(fa, protocol::fingerprint(b.public_key));
  EXPECT_EQ(protocol::serverOfMatch("lab-2-17"), "lab-2");
  EXPECT_EQ(protocol::serverOfMatch("nodash"), "");
}

}  // namespace
}  // namespace pool::net::test
