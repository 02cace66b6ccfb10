// The live aim's signed bytes (the envelope with tag Aim) cover every field, only the seat's key
// verifies them, the values are range-checked, and both wire forms carry them unchanged; the
// relayed form is sealed by the server like its other samples.
#include <gtest/gtest.h>

#include <functional>
#include <numbers>

#include "net/aim_convert.h"
#include "net/server_seal.h"
#include "protocol/aim_sample.h"
#include "protocol/command_signature.h"
#include "protocol/key_pair.h"

namespace pool::net {
namespace {

using namespace protocol;

AimSample sample() {
  AimSample a;
  a.match = "srv-3";
  a.seat = 1;
  a.seat_token = 0x0123456789abcdefULL;
  a.seq = 17;
  a.shot_number = 4;
  a.yaw = -2.5;
  a.tip_side = 0.2;
  a.tip_height = -0.3;
  a.elevation = 0.1;
  a.power = 0.6;
  a.stroke = false;
  a.cue_ball_x = -0.8;
  a.cue_ball_y = 0.2;
  return a;
}

TEST(AimSample, TheEncodingIsTheEnvelopeWithTagAim) {
  const auto bytes = signedBytes(sample());
  ASSERT_EQ(bytes.size(), kSignedAimBytes);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 8), "POOL-MSG");
  EXPECT_EQ(bytes[16], static_cast<std::uint8_t>(MessageTag::Aim));
  EXPECT_EQ(bytes[17], 5);
  EXPECT_EQ(std::string(bytes.begin() + 18, bytes.begin() + 23), "srv-3");
  // The body starts with the shot number, little-endian.
  EXPECT_EQ(bytes[kEnvelopeHeaderBytes], 4);
}

TEST(AimSample, OnlyTheSignersKeyVerifiesAndEveryFieldIsCovered) {
  const KeyPair key = generateKeyPair();
  const KeyPair other = generateKeyPair();
  AimSample signed_aim = sample();
  signAim(signed_aim, key);
  EXPECT_EQ(verifyAim(signed_aim, key.publicKey()), SignatureCheck::Valid);
  EXPECT_EQ(verifyAim(signed_aim, other.publicKey()), SignatureCheck::BadSignature);
  AimSample unsigned_aim = sample();
  EXPECT_EQ(verifyAim(unsigned_aim, key.publicKey()), SignatureCheck::Unsigned);

  const std::vector<std::function<void(AimSample&)>> changes{
      [](AimSample& a) { a.match = "srv-4"; },  [](AimSample& a) { a.seat = 0; },
      [](AimSample& a) { a.seat_token ^= 1; },  [](AimSample& a) { a.seq += 1; },
      [](AimSample& a) { a.shot_number += 1; }, [](AimSample& a) { a.yaw += 1e-9; },
      [](AimSample& a) { a.tip_side = 0.0; },   [](AimSample& a) { a.tip_height = 0.0; },
      [](AimSample& a) { a.elevation = 0.2; },  [](AimSample& a) { a.power = 0.61; },
      [](AimSample& a) { a.stroke = true; },    [](AimSample& a) { a.cue_ball_x = 0.0; },
      [](AimSample& a) { a.cue_ball_y = 0.0; },
  };
  for (std::size_t i = 0; i < changes.size(); ++i) {
    AimSample changed = signed_aim;
    changes[i](changed);
    EXPECT_EQ(verifyAim(changed, key.publicKey()), SignatureCheck::BadSignature) << "change " << i;
  }
}

TEST(AimSample, AnAimSignatureIsWorthlessAsAShotCommand) {
  const KeyPair key = generateKeyPair();
  AimSample aim = sample();
  signAim(aim, key);
  ShotRequest shot;
  shot.match = aim.match;
  shot.seat = aim.seat;
  shot.seat_token = aim.seat_token;
  shot.seq = aim.seq;
  shot.cue.yaw = aim.yaw;
  shot.cue.speed = 2.0;
  shot.signature = aim.signature;
  EXPECT_EQ(verifyCommand(shot, key.publicKey()), SignatureCheck::BadSignature);
}

TEST(AimSample, ValuesNoCueCanHaveAreRefused) {
  const CommandLimits limits;
  EXPECT_TRUE(checkAim(sample(), limits).ok());
  const std::vector<std::pair<std::function<void(AimSample&)>, std::string>> bad{
      {[](AimSample& a) { a.match.clear(); }, "match"},
      {[](AimSample& a) { a.seat = 2; }, "seat"},
      {[](AimSample& a) { a.yaw = std::numeric_limits<double>::quiet_NaN(); }, "values"},
      {[](AimSample& a) { a.power = std::numeric_limits<double>::infinity(); }, "values"},
      {[](AimSample& a) { a.yaw = 7.0; }, "yaw"},
      {[](AimSample& a) { a.tip_side = 0.5; }, "tip"},
      {[](AimSample& a) { a.elevation = -0.01; }, "elevation"},
      {[](AimSample& a) { a.elevation = 1.6; }, "elevation"},
      {[](AimSample& a) { a.power = 1.01; }, "power"},
      {[](AimSample& a) { a.cue_ball_x = 1.3; }, "cue ball"},
  };
  for (const auto& [change, field] : bad) {
    AimSample a = sample();
    change(a);
    const auto check = checkAim(a, limits);
    EXPECT_FALSE(check.ok()) << field;
    EXPECT_EQ(check.error().rfind(field, 0), 0u) << field << ": " << check.error();
  }
}

TEST(AimSample, BothWireFormsCarryTheValuesAndTheRelayIsSealedByTheServer) {
  const KeyPair player = generateKeyPair();
  AimSample aim = sample();
  signAim(aim, player);
  auto command = toAimCommand(aim);
  auto back = fromWire(*command);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->match, aim.match);
  EXPECT_EQ(back->seat_token, aim.seat_token);
  EXPECT_EQ(back->seq, aim.seq);
  EXPECT_EQ(back->yaw, aim.yaw);
  EXPECT_EQ(back->cue_ball_y, aim.cue_ball_y);
  EXPECT_EQ(back->signature, aim.signature);
  EXPECT_EQ(verifyAim(*back, player.publicKey()), SignatureCheck::Valid);

  const KeyPair server = generateKeyPair();
  auto relayed = toCueAim(aim);
  seal(*relayed, server);
  const SealedSample sealed = sealedOf(*relayed);
  EXPECT_EQ(sealed.kind, PublishedKind::CueAim);
  EXPECT_EQ(sealed.server, "srv");
  EXPECT_EQ(verifyPublished(sealed), SignatureCheck::Valid);
  relayed->yaw += 0.1;  // a changed relay no longer verifies
  EXPECT_EQ(verifyPublished(sealedOf(*relayed)), SignatureCheck::BadSignature);
  relayed->yaw -= 0.1;
  auto read = fromWire(*relayed);
  ASSERT_TRUE(read) << read.error();
  EXPECT_EQ(read->seat_token, 0u);  // the token and the player's signature are not relayed
  EXPECT_TRUE(read->signature.empty());
  EXPECT_EQ(read->power, aim.power);

  relayed->power = 2.0;  // a relay with values no cue has is unreadable
  EXPECT_FALSE(fromWire(*relayed));
}

}  // namespace
}  // namespace pool::net
