// Every topic type crosses from a writer in one participant to a reader in another intact.
#include <gtest/gtest.h>

#include <cstring>

#include "net/convert.h"
#include "net/shot_command_check.h"
#include "net/topic.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "net_fixture.h"

namespace pool::net {
namespace {

using namespace protocol;

using namespace test;

/// Writes `sent` from one participant and returns what a reader in another took.
template <class T>
Sample<T> roundTrip(std::uint32_t domain, const T& sent, const QosProfile& qos) {
  Participant a(domain);
  Participant b(domain);
  Topic<T> topic_a(a);
  Topic<T> topic_b(b);
  Reader<T> reader(b, topic_b, qos);
  Writer<T> writer(a, topic_a, qos);
  EXPECT_TRUE(writer.waitForReaders(1, 5s));
  EXPECT_TRUE(reader.waitForWriters(1, 5s));
  const Status status = writer.write(sent);
  EXPECT_TRUE(status) << status.error;
  auto got = takeAtLeast(b, reader, 1);
  EXPECT_EQ(got.size(), 1u);
  return got.empty() ? Sample<T>() : std::move(got.front());
}

class RoundTrip : public NetTest {};

TEST_F(RoundTrip, MatchInfo) {
  pool_MatchInfo m{};
  setText(m.match, "srv-a-1");
  setText(m.server, "srv-a");
  setText(m.name, "Table 1");
  setText(m.table, "wpa-9ft");
  m.phase = pool_PHASE_ASSIGNED;
  setText(m.players[0], "Ada");
  setText(m.players[1], "Bob");
  m.seats_taken = 2;
  m.spectators = 17;
  m.protocol_version = kProtocolVersion;
  const auto got = roundTrip(kRoundTripLobby, m, qos::lobby());
  EXPECT_EQ(textOf(got->match), "srv-a-1");
  EXPECT_EQ(textOf(got->server), "srv-a");
  EXPECT_EQ(textOf(got->name), "Table 1");
  EXPECT_EQ(textOf(got->table), "wpa-9ft");
  EXPECT_EQ(got->phase, pool_PHASE_ASSIGNED);
  EXPECT_EQ(textOf(got->players[1]), "Bob");
  EXPECT_EQ(got->seats_taken, 2);
  EXPECT_EQ(got->spectators, 17u);
  EXPECT_EQ(got->protocol_version, kProtocolVersion);
}

TEST_F(RoundTrip, JoinRequestAndReply) {
  Sample<pool_JoinRequest> request;
  setText(request->client, "c0ffee");
  request->request = 3;
  request->protocol_version = kProtocolVersion;
  setText(request->match, "new");
  request->action = pool_JOIN_SEAT;
  request->seat = -1;
  setText(request->name, "Ada");
  request->seat_token = 99;
  auto key = resizeSequence(request->public_key, 32);
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<std::uint8_t>(i * 7);
  const auto got = roundTrip(kRoundTripJoin, *request, qos::joinRequest());
  EXPECT_EQ(textOf(got->client), "c0ffee");
  EXPECT_EQ(got->request, 3u);
  EXPECT_EQ(textOf(got->match), "new");
  EXPECT_EQ(got->action, pool_JOIN_SEAT);
  EXPECT_EQ(got->seat, -1);
  EXPECT_EQ(textOf(got->name), "Ada");
  EXPECT_EQ(got->seat_token, 99u);
  ASSERT_EQ(got->public_key._length, 32u);
  EXPECT_EQ(std::memcmp(got->public_key._buffer, request->public_key._buffer, 32), 0);

  pool_JoinReply reply{};
  setText(reply.client, "c0ffee");
  reply.request = 3;
  setText(reply.server, "srv-a");
  setText(reply.match, "srv-a-2");
  reply.action = pool_JOIN_SEAT;
  reply.outcome = pool_JOIN_SEAT_TAKEN;
  setText(reply.reason, "seat 1 is taken by Bob");
  reply.seat = 1;
  reply.seat_token = 0x1234567890abcdefull;
  const auto back = roundTrip(kRoundTripJoin, reply, qos::joinReply());
  EXPECT_EQ(textOf(back->match), "srv-a-2");
  EXPECT_EQ(back->outcome, pool_JOIN_SEAT_TAKEN);
  EXPECT_EQ(textOf(back->reason), "seat 1 is taken by Bob");
  EXPECT_EQ(back->seat, 1);
  EXPECT_EQ(back->seat_token, 0x1234567890abcdefull);
}

TEST_F(RoundTrip, ShotCommand) {
  ShotRequest r;
  r.match = "srv-a-1";
  r.seat = 1;
  r.seat_token = 7;
  r.seq = 12;
  r.cue = {1.25, -0.1, 0.3, 0.2, 4.5, false};
  r.called_ball = 11;
  r.called_pocket = "foot_right_corner";
  r.cue_ball_at = Eigen::Vector2d(-0.7, 0.1);
  r.option = ShotOption::PlayOn;
  r.signature.assign(64, 0x5a);
  const auto got = roundTrip(kRoundTripCommand, *toWire(r), qos::command());
  const auto back = fromWire(*got);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->match, r.match);
  EXPECT_EQ(back->seat, 1);
  EXPECT_EQ(back->seq, 12u);
  EXPECT_EQ(back->cue.yaw, 1.25);
  EXPECT_EQ(back->cue.speed, 4.5);
  EXPECT_EQ(back->called_ball, 11);
  EXPECT_EQ(back->called_pocket, "foot_right_corner");
  EXPECT_EQ(back->cue_ball_at, r.cue_ball_at);
  EXPECT_EQ(back->option, ShotOption::PlayOn);
  EXPECT_EQ(back->signature, r.signature);
  EXPECT_TRUE(validateShotCommand(*got).ok());
}

TEST_F(RoundTrip, ShotResultWithEventsAndVerdict) {
  physics::EventLog log;
  for (int i = 0; i < 500; ++i) {  // a long break's worth
    physics::Event e;
    e.t = i * 0.01;
    e.type = static_cast<physics::EventType>(i % 11);
    e.ball_a = i % 16;
    e.where = i % 3 ? "head_left" : "";
    e.speed = i * 0.001;
    e.pos = {i * 1e-3, -i * 1e-3, 0.028575};
    log.push_back(e);
  }
  Sample<pool_ShotResult> result;
  setText(result->match, "srv-a-1");
  result->seat = 0;
  result->seq = 5;
  result->shot_number = 9;
  result->accepted = true;
  result->reject_reason = pool_REJECT_NONE;
  ASSERT_TRUE(putEvents(result->events, log));
  resizeSequence(result->fouls, 2)[1] = pool_FOUL_WRONG_BALL_FIRST;
  resizeSequence(result->pocketed, 3)[2] = 12;
  result->next_shooter = 1;
  result->ball_in_hand = pool_IN_HAND_ANYWHERE;
  resizeSequence(result->options, 1)[0] = pool_OPTION_PLAY_ON;
  result->winner = -1;
  result->end = pool_END_NONE;
  setText(result->verdict_text, "foul wrong_ball_first; seat 1 next, ball in hand anywhere");

  const auto got = roundTrip(kRoundTripResult, *result, qos::result());
  EXPECT_EQ(got->seq, 5u);
  EXPECT_EQ(got->shot_number, 9u);
  EXPECT_TRUE(got->accepted);
  const auto events = getEvents(got->events);
  ASSERT_TRUE(events) << events.error();
  ASSERT_EQ(events->size(), log.size());
  EXPECT_EQ((*events)[499].pos, log[499].pos);
  EXPECT_EQ((*events)[499].type, log[499].type);
  EXPECT_EQ((*events)[1].where, "head_left");
  ASSERT_EQ(got->fouls._length, 2u);
  EXPECT_EQ(got->fouls._buffer[1], pool_FOUL_WRONG_BALL_FIRST);
  ASSERT_EQ(got->pocketed._length, 3u);
  EXPECT_EQ(got->pocketed._buffer[2], 12);
  EXPECT_EQ(got->ball_in_hand, pool_IN_HAND_ANYWHERE);
  EXPECT_EQ(got->options._buffer[0], pool_OPTION_PLAY_ON);
  EXPECT_EQ(textOf(got->verdict_text), textOf(result->verdict_text));
}

TEST_F(RoundTrip, TableSnapshot) {
  std::vector<physics::Ball> balls;
  for (int id = 0; id < 16; ++id) balls.push_back(oddBall(id));
  Sample<pool_TableSnapshot> snapshot;
  setText(snapshot->match, "srv-a-1");
  snapshot->frame = 61;
  snapshot->sim_time = 61.0 / 60.0;
  snapshot->shot_number = 4;
  ASSERT_TRUE(putBalls(snapshot->balls, balls));
  const auto got = roundTrip(kRoundTripSnapshot, *snapshot, qos::snapshot());
  EXPECT_EQ(got->frame, 61u);
  EXPECT_EQ(got->sim_time, 61.0 / 60.0);
  const auto back = getBalls(got->balls);
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->size(), 16u);
  for (int id = 0; id < 16; ++id) {
    EXPECT_EQ((*back)[id].pos, balls[id].pos);
    EXPECT_EQ((*back)[id].ang_vel, balls[id].ang_vel);
    EXPECT_EQ((*back)[id].orient.coeffs(), balls[id].orient.coeffs());
    EXPECT_EQ((*back)[id].state, balls[id].state);
  }
}

TEST_F(RoundTrip, MatchState) {
  Sample<pool_MatchState> state;
  setText(state->match, "srv-a-1");
  state->revision = 30;
  state->phase = pool_PHASE_ASSIGNED;
  setText(state->seats[0].name, "Ada");
  state->seats[0].connected = true;
  state->seats[0].group = pool_GROUP_STRIPES;
  state->seats[0].balls_left = 3;
  state->seats[1].fouls = 2;
  state->seats[1].racks_won = 1;
  state->shooter = 1;
  state->breaker = 0;
  state->rack = 2;
  state->shot_number = 14;
  state->ball_in_hand = pool_IN_HAND_BEHIND_HEAD_STRING;
  resizeSequence(state->options, 2)[1] = pool_OPTION_OPPONENT_REBREAKS;
  state->shot_clock = 27.5;
  state->winner = -1;
  state->end = pool_END_NONE;
  setText(state->last_verdict, "legal; seat 1 next");
  physics::Ball pocketed = oddBall(5);
  pocketed.state = physics::MotionState::Pocketed;
  pocketed.pocket = "right_side";
  const std::vector<physics::Ball> layout{oddBall(0), pocketed};
  ASSERT_TRUE(putBalls(state->balls, layout));

  const auto got = roundTrip(kRoundTripState, *state, qos::state());
  EXPECT_EQ(got->revision, 30u);
  EXPECT_EQ(textOf(got->seats[0].name), "Ada");
  EXPECT_TRUE(got->seats[0].connected);
  EXPECT_EQ(got->seats[0].group, pool_GROUP_STRIPES);
  EXPECT_EQ(got->seats[1].racks_won, 1);
  EXPECT_EQ(got->ball_in_hand, pool_IN_HAND_BEHIND_HEAD_STRING);
  EXPECT_EQ(got->options._buffer[1], pool_OPTION_OPPONENT_REBREAKS);
  EXPECT_EQ(got->shot_clock, 27.5);
  const auto balls = getBalls(got->balls);
  ASSERT_TRUE(balls) << balls.error();
  ASSERT_EQ(balls->size(), 2u);
  EXPECT_EQ((*balls)[1].pocket, "right_side");
  EXPECT_EQ((*balls)[1].state, physics::MotionState::Pocketed);
}

}  // namespace
}  // namespace pool::net
