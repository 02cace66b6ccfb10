// Requests off the wire become domain commands or refusals; what the server publishes of a match
// crosses the wire intact.
#include <gtest/gtest.h>

#include <limits>

#include "match_fixture.h"
#include "net/convert.h"
#include "net/message_convert.h"
#include "net/shot_command_check.h"
#include "net/wire_fields.h"
#include "server/match_publish.h"

namespace pool::server {
namespace {

using namespace test;

protocol::CommandLimits nineFootLimits() {
  return commandLimits(nineFoot()->spec);
}

TEST(ReadCommand, AGoodCommandBecomesAShotRequest) {
  const auto wire = net::toWire(breakShot(3));
  const net::IncomingCommand read = net::readCommand(*wire, nineFootLimits());
  ASSERT_TRUE(read.request) << read.problem;
  EXPECT_EQ(read.request->match, "srv-1");
  EXPECT_EQ(read.request->seq, 3u);
  EXPECT_EQ(read.request->cue.speed, 8.0);
  // The signature crosses unchanged and still verifies against the signer's key.
  EXPECT_EQ(read.request->signature, breakShot(3).signature);
  EXPECT_EQ(protocol::verifyCommand(*read.request, publicKeyOf("a")),
            protocol::SignatureCheck::Valid);
}

TEST(ReadCommand, UnreadableFieldsAreMalformedWithTheSeatAndSeqEchoed) {
  auto unknown_option = net::toWire(breakShot(4));
  net::setRawValue(unknown_option->option, 42);
  net::IncomingCommand read = net::readCommand(*unknown_option, nineFootLimits());
  EXPECT_FALSE(read.request);
  EXPECT_FALSE(read.bad_signature);
  EXPECT_EQ(read.seq, 4u);
  EXPECT_NE(read.problem.find("option"), std::string::npos);

  auto nan = net::toWire(breakShot(5));
  nan->yaw = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(net::readCommand(*nan, nineFootLimits()).request);

  auto off_table = net::toWire(breakShot(6));
  off_table->has_cue_ball_placement = true;
  off_table->cue_ball_x = 3.0;
  EXPECT_FALSE(net::readCommand(*off_table, nineFootLimits()).request);
}

TEST(ReadCommand, AnOversizedSignatureIsABadSignature) {
  auto signed_too_much = net::toWire(breakShot(7));
  signed_too_much->signature._length = 65;
  const net::IncomingCommand read = net::readCommand(*signed_too_much, nineFootLimits());
  signed_too_much->signature._length = 0;
  EXPECT_FALSE(read.request);
  EXPECT_TRUE(read.bad_signature);
}

TEST(ReadCommand, TheServersLimitsSpanItsLargestTable) {
  // One check reads every command before its match: a snooker table's spot (the black's, beyond
  // the 9-ft table's end) passes it; beyond the snooker table's cushions nothing does.
  const protocol::CommandLimits limits = serverLimits(nineFoot()->spec);
  EXPECT_EQ(limits.half_length, 3.569 / 2);
  EXPECT_EQ(limits.half_width, 1.778 / 2);
  EXPECT_EQ(limits.max_speed, nineFootLimits().max_speed);
  EXPECT_EQ(limits.miscue_limit, nineFootLimits().miscue_limit);
  auto in_the_d = net::toWire(breakShot(8));
  in_the_d->has_cue_ball_placement = true;
  in_the_d->cue_ball_x = -1.3;  // in snooker's D, past the 9-ft table's head cushion
  EXPECT_FALSE(net::readCommand(*in_the_d, nineFootLimits()).request);
  EXPECT_TRUE(net::readCommand(*in_the_d, limits).request);
  in_the_d->cue_ball_x = -1.8;
  EXPECT_FALSE(net::readCommand(*in_the_d, limits).request);
}

TEST(JoinCommandFromWire, UnknownActionsAreRefused) {
  pool_JoinRequest r{};
  net::setText(r.client, "c1");
  net::setText(r.match, "srv-1");
  r.action = pool_JOIN_REJOIN;
  r.seat_token = 77;
  const auto command = net::fromWire(r);
  ASSERT_TRUE(command);
  EXPECT_EQ(command->action, JoinAction::Rejoin);
  EXPECT_EQ(command->token, 77u);
  net::setRawValue(r.action, 9);
  EXPECT_FALSE(net::fromWire(r));
}

TEST(JoinCommandFromWire, ThePublicKeyIsCarriedOver) {
  net::Sample<pool_JoinRequest> sample;
  pool_JoinRequest& r = *sample;
  net::setText(r.client, "c1");
  net::setText(r.match, "srv-1");
  r.action = pool_JOIN_SEAT;
  const auto none = net::fromWire(r);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->public_key.empty());
  const auto key = publicKeyOf("c1");
  auto field = net::resizeSequence(r.public_key, static_cast<std::uint32_t>(key.size()));
  std::copy(key.begin(), key.end(), field.begin());
  const auto command = net::fromWire(r);
  ASSERT_TRUE(command);
  EXPECT_EQ(command->public_key, key);
}

TEST(MatchPublish, MatchStateShowsSeatsTurnAndLayout) {
  auto m = seatedMatch();
  const auto st = net::toWire(matchViewOf(*m));
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
  const auto info_sample = net::toWire(lobbyEntryOf(*m, "srv"));
  const pool_MatchInfo& info = *info_sample;
  EXPECT_EQ(info.seats_taken, 2);
  EXPECT_EQ(net::textOf(info.table), "wpa-9ft");
}

TEST(MatchPublish, AFinalResultCarriesEventsAndVerdict) {
  MatchOptions fast;
  fast.unpaced = true;
  auto m = seatedMatch(fast);
  const CommandAnswer answer = m->handleShot(breakShot(1), 0.0);
  const auto first = net::toWire(commandReport(m->id(), answer));
  EXPECT_TRUE(first->accepted);
  EXPECT_EQ(first->events._length, 0u);
  EXPECT_EQ(first->verdict_text[0], '\0');
  const auto report = finishNow(*m);
  ASSERT_TRUE(report);
  const auto last = net::toWire(finalReport(m->id(), *report));
  EXPECT_EQ(last->events._length, report->events.size());
  EXPECT_EQ(last->shot_number, 1u);
  EXPECT_NE(last->verdict_text[0], '\0');
  EXPECT_EQ(last->next_shooter, report->verdict.next_shooter);
}

}  // namespace
}  // namespace pool::server
