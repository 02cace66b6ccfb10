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
  EXPECT_EQ(problem([](auto& c) { c.balls._buffer[1].id = 22; }).rfind("balls:", 0), 0u);
  EXPECT_NE(problem([](auto& c) { c.balls._buffer[1].id = 0; }).find("twice"), std::string::npos);
  EXPECT_EQ(problem([](auto& c) {
              c.balls._buffer[0].x = std::numeric_limits<double>::quiet_NaN();
            }).rfind("balls:", 0),
            0u);
  EXPECT_NE(problem([](auto& c) { c.balls._buffer[0].y = 0.7; }).find("off the table"),
            std::string::npos);
  EXPECT_EQ(problem([](auto& c) { c.rack = 7; }).rfind("rack:", 0), 0u);
  EXPECT_EQ(problem([](auto& c) { resizeSequence(c.balls, 23); }), "balls: at most 22");
  EXPECT_EQ(problem([](auto& c) { c.coefficients[2] = HUGE_VAL; }).rfind("spin_decel:", 0), 0u);
}

/// A snooker layout: the cue ball and every ball 1-21, each on a spot of its own (m).
PracticeRequest snookerLayout() {
  PracticeRequest r = layout();
  r.balls.clear();
  for (int id = 0; id <= physics::kMaxBallId; ++id) r.balls.push_back({id, 0.08 * id - 0.8, 0.3});
  r.balls.back().x = 1.46;  // the black on its spot, beyond a pool table's end
  return r;
}

TEST(PracticeCommand, ASnookerLayoutOfTwentyTwoBallsIsSignedWholeAndReadsBack) {
  // Past the 16 fixed slots, one slot a ball: a pool command encodes as before.
  const PracticeRequest r = snookerLayout();
  ASSERT_EQ(r.balls.size(), 22u);
  EXPECT_EQ(protocol::signedBytes(r).size(),
            protocol::kSignedPracticeBytes + 6 * protocol::kPracticeSlotBytes);
  PracticeRequest sixteen = r;
  sixteen.balls.resize(16);
  EXPECT_EQ(protocol::signedBytes(sixteen).size(), protocol::kSignedPracticeBytes);

  // Every ball is signed, the last one included.
  const auto key = protocol::generateKeyPair();
  PracticeRequest signed_layout = r;
  protocol::signPractice(signed_layout, key);
  EXPECT_EQ(protocol::verifyPractice(signed_layout, key.publicKey()),
            protocol::SignatureCheck::Valid);
  PracticeRequest moved = signed_layout;
  moved.balls.back().y += 1e-9;
  EXPECT_EQ(protocol::verifyPractice(moved, key.publicKey()),
            protocol::SignatureCheck::BadSignature);
  PracticeRequest dropped = signed_layout;
  dropped.balls.pop_back();
  EXPECT_EQ(protocol::verifyPractice(dropped, key.publicKey()),
            protocol::SignatureCheck::BadSignature);

  // Through a sample on a snooker table's surface (3.569 x 1.778 m): all 22, as signed.
  protocol::CommandLimits snooker;
  snooker.half_length = 3.569 / 2;
  snooker.half_width = 1.778 / 2;
  const IncomingPractice in = readPractice(*toWire(signed_layout), snooker);
  ASSERT_TRUE(in.request) << in.problem;
  ASSERT_EQ(in.request->balls.size(), 22u);
  EXPECT_EQ(in.request->balls[21].id, 21);
  EXPECT_EQ(in.request->balls[21].x, 1.46);
  EXPECT_EQ(protocol::verifyPractice(*in.request, key.publicKey()),
            protocol::SignatureCheck::Valid);
}

TEST(PracticeCommand, ARackIsAGamesNumberOrZero) {
  PracticeRequest rack = layout();
  rack.action = PracticeAction::Rack;
  rack.balls.clear();
  for (const int game : {0, 8, 9, 10, 3, 22}) {
    rack.rack = game;
    EXPECT_TRUE(readPractice(*toWire(rack)).request) << game;
  }
  rack.rack = 7;
  const IncomingPractice seven = readPractice(*toWire(rack));
  EXPECT_FALSE(seven.request);
  EXPECT_EQ(seven.problem, "rack: must be a game's number (8, 9, 10, 3, 22) or 0 (clear)");
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
  // Of any game: snooker and three-cushion practise on their own tables, with no race and no
  // clock either.
  for (const rules::Game game : {rules::Game::Snooker, rules::Game::ThreeCushion}) {
    protocol::MatchSettings s;
    s.game = game;
    s.practice = true;
    EXPECT_TRUE(protocol::checkSettings(s).ok()) << rules::toString(game);
    s.race_to = 2;
    const auto raced = protocol::checkSettings(s);
    ASSERT_FALSE(raced.ok());
    EXPECT_EQ(raced.error(), "practice: a practice table has no race and no shot clock");
    s.race_to = 1;
    s.shot_clock = 30;
    EXPECT_FALSE(protocol::checkSettings(s).ok()) << rules::toString(game);
  }
}

}  // namespace
}  // namespace pool::net::test
