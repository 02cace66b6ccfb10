// Requests off the wire: field checks become refusals, good ones become domain commands.
#include <gtest/gtest.h>

#include <limits>

#include "match_fixture.h"
#include "net/convert.h"
#include "net/wire_fields.h"
#include "wire_messages.h"
#include "wire_requests.h"

namespace pool::server {
namespace {

using namespace test;

protocol::CommandLimits nineFootLimits() {
  return commandLimits(nineFoot()->spec);
}

TEST(ReadCommand, AGoodCommandBecomesAShotRequest) {
  const auto wire = net::toWire(breakShot(3));
  const ReadCommand read = readCommand(*wire, nineFootLimits());
  ASSERT_TRUE(read.refusal.accepted()) << read.refusal.rejection.text;
  EXPECT_EQ(read.request.match, "srv-1");
  EXPECT_EQ(read.request.seq, 3u);
  EXPECT_EQ(read.request.cue.speed, 8.0);
  // The signature crosses unchanged and still verifies against the signer's key.
  EXPECT_EQ(read.request.signature, breakShot(3).signature);
  EXPECT_EQ(protocol::verifyCommand(read.request, publicKeyOf("a")),
            protocol::SignatureCheck::Valid);
}

TEST(ReadCommand, UnreadableFieldsAreMalformedWithTheSeatAndSeqEchoed) {
  auto unknown_option = net::toWire(breakShot(4));
  net::setRawValue(unknown_option->option, 42);
  ReadCommand read = readCommand(*unknown_option, nineFootLimits());
  EXPECT_EQ(read.refusal.rejection.reason, Reject::Malformed);
  EXPECT_EQ(read.refusal.seq, 4u);
  EXPECT_NE(read.refusal.rejection.text.find("option"), std::string::npos);

  auto nan = net::toWire(breakShot(5));
  nan->yaw = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(readCommand(*nan, nineFootLimits()).refusal.rejection.reason, Reject::Malformed);

  auto off_table = net::toWire(breakShot(6));
  off_table->has_cue_ball_placement = true;
  off_table->cue_ball_x = 3.0;
  EXPECT_EQ(readCommand(*off_table, nineFootLimits()).refusal.rejection.reason, Reject::Malformed);
}

TEST(ReadCommand, AnOversizedSignatureIsABadSignature) {
  auto signed_too_much = net::toWire(breakShot(7));
  signed_too_much->signature._length = 65;
  const ReadCommand read = readCommand(*signed_too_much, nineFootLimits());
  signed_too_much->signature._length = 0;
  EXPECT_EQ(read.refusal.rejection.reason, Reject::BadSignature);
}

TEST(JoinCommandFromWire, UnknownActionsAreRefused) {
  pool_JoinRequest r{};
  net::setText(r.client, "c1");
  net::setText(r.match, "srv-1");
  r.action = pool_JOIN_REJOIN;
  r.seat_token = 77;
  const auto command = joinCommand(r);
  ASSERT_TRUE(command);
  EXPECT_EQ(command->action, JoinAction::Rejoin);
  EXPECT_EQ(command->token, 77u);
  net::setRawValue(r.action, 9);
  EXPECT_FALSE(joinCommand(r));
  const pool_JoinReply reply = unreadableJoinReply(r, "bad", "srv");
  EXPECT_EQ(reply.outcome, pool_JOIN_NOT_ALLOWED);
  EXPECT_EQ(net::textOf(reply.client), "c1");
}

TEST(JoinCommandFromWire, ThePublicKeyIsCarriedOver) {
  net::Sample<pool_JoinRequest> sample;
  pool_JoinRequest& r = *sample;
  net::setText(r.client, "c1");
  net::setText(r.match, "srv-1");
  r.action = pool_JOIN_SEAT;
  const auto none = joinCommand(r);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->public_key.empty());
  const auto key = publicKeyOf("c1");
  auto field = net::resizeSequence(r.public_key, static_cast<std::uint32_t>(key.size()));
  std::copy(key.begin(), key.end(), field.begin());
  const auto command = joinCommand(r);
  ASSERT_TRUE(command);
  EXPECT_EQ(command->public_key, key);
}

TEST(WireMessages, MatchStateShowsSeatsTurnAndLayout) {
  auto m = seatedMatch();
  const auto st = matchState(*m);
  EXPECT_EQ(net::textOf(st->match), "srv-1");
  EXPECT_EQ(st->phase, pool_PHASE_BREAK);
  EXPECT_EQ(net::textOf(st->seats[0].name), "Ada");
  EXPECT_TRUE(st->seats[1].connected);
  EXPECT_EQ(st->seats[0].balls_left, 7);
  EXPECT_EQ(st->shooter, 0);
  EXPECT_EQ(st->ball_in_hand, pool_IN_HAND_BEHIND_HEAD_STRING);
  EXPECT_EQ(st->balls._length, 16u);
  EXPECT_LT(st->shot_clock, 0.0);
  EXPECT_EQ(st->winner, -1);
  const pool_MatchInfo info = matchInfo(*m, "srv");
  EXPECT_EQ(info.seats_taken, 2);
  EXPECT_EQ(net::textOf(info.table), "wpa-9ft");
}

TEST(WireMessages, AFinalResultCarriesEventsAndVerdict) {
  MatchOptions fast;
  fast.unpaced = true;
  auto m = seatedMatch(fast);
  const CommandAnswer answer = m->handleShot(breakShot(1), 0.0);
  const auto first = commandResult(m->id(), answer);
  EXPECT_TRUE(first->accepted);
  EXPECT_EQ(first->events._length, 0u);
  EXPECT_EQ(first->verdict_text[0], '\0');
  const auto report = finishNow(*m);
  ASSERT_TRUE(report);
  const auto last = finalResult(m->id(), *report);
  EXPECT_EQ(last->events._length, report->events.size());
  EXPECT_EQ(last->shot_number, 1u);
  EXPECT_NE(last->verdict_text[0], '\0');
  EXPECT_EQ(last->next_shooter, report->verdict.next_shooter);
}

}  // namespace
}  // namespace pool::server
