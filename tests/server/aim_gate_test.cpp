// The server's gate on live aims: only the shooter's holding, this turn, in order, signed by the
// seat's key and at a bounded rate is relayed; each refusal is counted under its reason.
#include <gtest/gtest.h>

#include "protocol/key_pair.h"
#include "server/match/aim_gate.h"

namespace pool::server {
namespace {

struct Fixture {
  protocol::KeyPair shooter_key = protocol::generateKeyPair();
  AimTurn turn;
  Fixture() {
    turn.aiming = true;
    turn.shooter = 1;
    turn.shot_number = 7;
    turn.token = 99;
    turn.public_key = shooter_key.publicKey();
  }
  protocol::AimSample aim(std::uint32_t seq, const protocol::KeyPair* key = nullptr) const {
    protocol::AimSample a;
    a.match = "t-1";
    a.seat = 1;
    a.seat_token = 99;
    a.seq = seq;
    a.shot_number = 7;
    a.yaw = 0.001 * seq;
    a.power = 0.5;
    protocol::signAim(a, key ? *key : shooter_key);
    return a;
  }
};

TEST(AimGate, TheShootersSignedAimsAreRelayedInOrder) {
  Fixture f;
  AimGate gate;
  EXPECT_EQ(gate.check(f.aim(1), &f.turn, 0.0), AimDrop::None);
  EXPECT_EQ(gate.check(f.aim(3), &f.turn, 0.1), AimDrop::None);
  EXPECT_EQ(gate.relayed(), 2u);
}

TEST(AimGate, EachRefusalHasItsReasonAndIsCounted) {
  Fixture f;
  AimGate gate;
  const protocol::KeyPair stranger = protocol::generateKeyPair();
  auto check = [&](protocol::AimSample a, const AimTurn* turn = nullptr) {
    return gate.check(a, turn ? turn : &f.turn, 0.5);
  };
  protocol::AimSample bad = f.aim(1);
  bad.power = 3.0;
  EXPECT_EQ(check(bad), AimDrop::Malformed);
  EXPECT_EQ(gate.check(f.aim(1), nullptr, 0.5), AimDrop::NoSuchMatch);
  AimTurn moving = f.turn;
  moving.aiming = false;
  EXPECT_EQ(check(f.aim(1), &moving), AimDrop::NotAiming);
  protocol::AimSample other_seat = f.aim(1);
  other_seat.seat = 0;
  protocol::signAim(other_seat, stranger);  // the other player's own key: still not the shooter
  EXPECT_EQ(check(other_seat), AimDrop::NotShooter);
  AimTurn banned = f.turn;
  banned.banned = true;
  EXPECT_EQ(check(f.aim(1), &banned), AimDrop::NotShooter);
  protocol::AimSample old_holding = f.aim(1);
  old_holding.seat_token = 98;
  protocol::signAim(old_holding, f.shooter_key);
  EXPECT_EQ(check(old_holding), AimDrop::BadToken);
  protocol::AimSample last_turn = f.aim(1);
  last_turn.shot_number = 6;
  protocol::signAim(last_turn, f.shooter_key);
  EXPECT_EQ(check(last_turn), AimDrop::OtherTurn);
  EXPECT_EQ(check(f.aim(2, &stranger)), AimDrop::BadSignature);
  protocol::AimSample unsigned_aim = f.aim(2);
  unsigned_aim.signature.clear();
  EXPECT_EQ(check(unsigned_aim), AimDrop::BadSignature);
  // The shooter's own, then the same again (a replay) and an older one.
  EXPECT_EQ(check(f.aim(5)), AimDrop::None);
  EXPECT_EQ(check(f.aim(5)), AimDrop::Stale);
  EXPECT_EQ(check(f.aim(4)), AimDrop::Stale);
  for (const AimDrop d : {AimDrop::Malformed, AimDrop::NoSuchMatch, AimDrop::NotAiming,
                          AimDrop::BadToken, AimDrop::OtherTurn}) {
    EXPECT_EQ(gate.dropped(d), 1u) << toString(d);
  }
  EXPECT_EQ(gate.dropped(AimDrop::NotShooter), 2u);
  EXPECT_EQ(gate.dropped(AimDrop::BadSignature), 2u);
  EXPECT_EQ(gate.dropped(AimDrop::Stale), 2u);
  EXPECT_EQ(gate.relayed(), 1u);
}

TEST(AimGate, ANewTurnNumbersAfresh) {
  Fixture f;
  AimGate gate;
  EXPECT_EQ(gate.check(f.aim(40), &f.turn, 0.0), AimDrop::None);
  f.turn.shot_number = 8;
  protocol::AimSample next = f.aim(1);
  next.shot_number = 8;
  protocol::signAim(next, f.shooter_key);
  EXPECT_EQ(gate.check(next, &f.turn, 0.1), AimDrop::None);
  // The old turn's sample no longer passes, whatever its number.
  EXPECT_EQ(gate.check(f.aim(41), &f.turn, 0.2), AimDrop::OtherTurn);
}

TEST(AimGate, AFloodCostsAtMostTheRateInSignatureChecksASecond) {
  Fixture f;
  AimGate gate(AimRates{10});
  const protocol::KeyPair stranger = protocol::generateKeyPair();
  // 100 forged samples with rising numbers within one second: 10 are checked, 90 dropped unread.
  for (std::uint32_t i = 1; i <= 100; ++i) gate.check(f.aim(i, &stranger), &f.turn, 0.001 * i);
  EXPECT_EQ(gate.dropped(AimDrop::BadSignature), 10u);
  EXPECT_EQ(gate.dropped(AimDrop::Flood), 90u);
  // The next second the shooter's own aim passes again (its number above the forged ones').
  EXPECT_EQ(gate.check(f.aim(101), &f.turn, 1.2), AimDrop::None);
}

}  // namespace
}  // namespace pool::server
