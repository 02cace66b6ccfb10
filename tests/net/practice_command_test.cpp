// Practice commands on the wire: their signed bytes (tag Practice, every field covered), the
// sample round trip, and the field checks a server makes before anything else.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "net/practice_convert.h"
#include "net/wire_fields.h"
#include "protocol/command_signature.h"
#include "protocol/practice_request.h"
#include "protocol/seat_request.h"

namespace pool::net::test {
namespace {

using protocol::PracticeAction;
using protocol::PracticeRequest;

PracticeRequest layout() {
  PracticeRequest r;
  r.match = "srv-2";
  r.seat = 1;
  r.seat_token = 0x1234;
  r.seq = 7;
  r.action = PracticeAction::Layout;
  r.balls = {{0, -0.6, 0.1}, {9, 0.3, -0.2}};
  return r;
}

TEST(PracticeCommand, TheEncodingIsTheEnvelopeWithTagPracticeAndAFixedLayout) {
  const auto bytes = protocol::signedBytes(layout());
  ASSERT_EQ(bytes.size(), protocol::kSignedPracticeBytes);
  EXPECT_EQ(bytes[16], static_cast<std::uint8_t>(protocol::MessageTag::Practice));
  PracticeRequest rack = layout();
  rack.action = PracticeAction::Rack;
  rack.balls.clear();
  EXPECT_EQ(protocol::signedBytes(rack).size(), protocol::kSignedPracticeBytes);
}

TEST(PracticeCommand, EveryFieldIsSignedAndOnlyTheSignersKeyVerifies) {
  const auto key = protocol::generateKeyPair();
  const auto other = protocol::generateKeyPair();
  PracticeRequest r = layout();
  protocol::signPractice(r, key);
  EXPECT_EQ(protocol::verifyPractice(r, key.publicKey()), protocol::SignatureCheck::Valid);
  EXPECT_EQ(protocol::verifyPractice(r, other.publicKey()), protocol::SignatureCheck::BadSignature);
  const std::vector<std::function<void(PracticeRequest&)>> changes = {
      [](PracticeRequest& c) { c.match = "srv-3"; },
      [](PracticeRequest& c) { c.seat = 0; },
      [](PracticeRequest& c) { c.seat_token += 1; },
      [](PracticeRequest& c) { c.seq += 1; },
      [](PracticeRequest& c) { c.action = PracticeAction::Undo; },
      [](PracticeRequest& c) { c.rack = 9; },
      [](PracticeRequest& c) { c.balls[1].x += 1e-9; },
      [](PracticeRequest& c) { c.balls.pop_back(); },
      [](PracticeRequest& c) { c.coefficients[6] = 0.4; },
  };
  for (std::size_t i = 0; i < changes.size(); ++i) {
    PracticeRequest changed = r;
    changes[i](changed);
    EXPECT_EQ(protocol::verifyPractice(changed, key.publicKey()),
              protocol::SignatureCheck::BadSignature)
        << "change " << i;
  }
  // A shot command's signature never passes for a practice command of the same numbers.
  protocol::ShotRequest shot;
  shot.match = r.match;
  shot.seat = r.seat;
  shot.seat_token = r.seat_token;
  shot.seq = r.seq;
  protocol::signCommand(shot, key);
  PracticeRequest borrowed = r;
  borrowed.signature = shot.signature;
  EXPECT_EQ(protocol::verifyPractice(borrowed, key.publicKey()),
            protocol::SignatureCheck::BadSignature);
}

TEST(PracticeCommand, ASampleReadsBackAsSent) {
  PracticeRequest r = layout();
  r.coefficients = {0.2, 0.01, 10.9, 0.95, 0.85, 0.2, 0.5};
  protocol::signPractice(r, protocol::generateKeyPair());
  const auto sample = toWire(r);
  const IncomingPractice in = readPractice(*sample);
  ASSERT_TRUE(in.request) << in.problem;
  EXPECT_EQ(in.request->match, r.match);
  EXPECT_EQ(in.request->seat, r.seat);
  EXPECT_EQ(in.request->seat_token, r.seat_token);
  EXPECT_EQ(in.request->seq, r.seq);
  EXPECT_EQ(in.request->action, r.action);
  ASSERT_EQ(in.request->balls.size(), 2u);
  EXPECT_EQ(in.request->balls[1].id, 9);
  EXPECT_EQ(in.request->balls[1].y, -0.2);
  EXPECT_EQ(in.request->coefficients, r.coefficients);
  EXPECT_EQ(in.request->signature, r.signature);
  EXPECT_EQ(protocol::signedBytes(*in.request), protocol::signedBytes(r));
}

TEST(PracticeCommand, FieldsThatCannotBeRightAreRefusedWithTheirName) {
  const auto problem = [](const std::function<void(pool_PracticeCommand&)>& spoil) {
    auto sample = toWire(layout());
    spoil(*sample);
    const IncomingPractice in = readPractice(*sample);
    EXPECT_FALSE(in.request);
    return in.problem;
  };
  EXPECT_EQ(problem([](auto& c) { setText(c.match, ""); }).rfind("match:", 0), 0u);
  EXPECT_EQ(problem([](auto& c) { c.seat = 2; }).rfind("seat:", 0), 0u);
  EXPECT_EQ(problem([](auto& c) { setRawValue(c.action, 9); }).rfind("action:", 0), 0u);
  EXPECT_EQ(problem([](auto& c) { c.balls._buffer[1].id = 16; }).rfind("balls:", 0), 0u);
  EXPECT_NE(problem([](auto& c) { c.balls._buffer[1].id = 0; }).find("twice"), std::string::npos);
  EXPECT_EQ(problem([](auto& c) {
              c.balls._buffer[0].x = std::numeric_limits<double>::quiet_NaN();
            }).rfind("balls:", 0),
            0u);
  EXPECT_NE(problem([](auto& c) { c.balls._buffer[0].y = 0.7; }).find("off the table"),
            std::string::npos);
  EXPECT_EQ(problem([](auto& c) { c.rack = 7; }).rfind("rack:", 0), 0u);
  EXPECT_EQ(problem([](auto& c) { c.coefficients[2] = HUGE_VAL; }).rfind("spin_decel:", 0), 0u);
}

TEST(PracticeCommand, CoefficientsOutsideTheirRangesAreRefusedByName) {
  const table::PhysicsParams standard;
  auto values = protocol::coefficientsOf(standard);
  EXPECT_TRUE(protocol::withCoefficients(standard, values));
  values[4] = 1.2;  // e_c above 1
  const auto refused = protocol::withCoefficients(standard, values);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().rfind("e_c:", 0), 0u) << refused.error();
  values = protocol::coefficientsOf(standard);
  values[0] = -0.1;  // u_s
  EXPECT_FALSE(protocol::withCoefficients(standard, values));
}

TEST(PracticeCommand, ThePracticeSettingIsSignedAndChecked) {
  protocol::SeatRequest r;
  r.match = "new";
  r.action = protocol::JoinAction::Seat;
  r.settings = protocol::MatchSettings{};
  const auto key = protocol::generateKeyPair();
  protocol::signSeatRequest(r, key);
  protocol::SeatRequest practice = r;
  practice.settings->practice = true;
  EXPECT_NE(protocol::signedBytes(practice), protocol::signedBytes(r));
  EXPECT_EQ(protocol::verifySeatRequest(practice, key.publicKey()),
            protocol::SignatureCheck::BadSignature);
  // A practice table has no race and no shot clock.
  EXPECT_TRUE(protocol::checkSettings(*practice.settings).ok());
  practice.settings->race_to = 3;
  EXPECT_FALSE(protocol::checkSettings(*practice.settings).ok());
  practice.settings->race_to = 1;
  practice.settings->shot_clock = 30;
  EXPECT_FALSE(protocol::checkSettings(*practice.settings).ok());
}

}  // namespace
}  // namespace pool::net::test
