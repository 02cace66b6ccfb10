// The client library's pure parts: lobby ordering and choice, the snapshot buffer, the rules'
// view of a match state, and reading malformed wire samples without asserting.
#include <gtest/gtest.h>

#include "client/net/lobby.h"
#include "client/net/snapshot_buffer.h"
#include "net/message_convert.h"
#include "net/wire_fields.h"

namespace pool::client::test {
namespace {

LobbyEntry entry(const std::string& id, MatchPhase phase, int seats) {
  LobbyEntry e;
  e.match = id;
  e.phase = phase;
  e.seats_taken = seats;
  return e;
}

TEST(LobbyTest, LowestNumberedMatchWithAFreeSeatIsChosen) {
  Lobby lobby;
  lobby.update(entry("a-10", MatchPhase::Lobby, 0));
  lobby.update(entry("a-2", MatchPhase::Lobby, 1));
  lobby.update(entry("a-1", MatchPhase::Open, 2));
  lobby.update(entry("b-3", MatchPhase::Over, 0));
  EXPECT_EQ(lobby.lowestWithFreeSeat(), "a-2");
  EXPECT_EQ(lobby.firstInPlay(), "a-1");
  lobby.remove("a-2");
  EXPECT_EQ(lobby.lowestWithFreeSeat(), "a-10");
  EXPECT_TRUE(matchOrder("x-9", "x-10"));
  EXPECT_FALSE(matchOrder("x-10", "x-9"));
}

TableFrame frame(std::uint32_t shot, std::uint32_t n, double t, double x) {
  TableFrame f;
  f.shot_number = shot;
  f.frame = n;
  f.sim_time = t;
  physics::Ball b;
  b.pos = physics::Vec3(x, 0, 0.028575);
  f.balls = {b};
  return f;
}

TEST(SnapshotBufferTest, InterpolatesAndDropsStaleFrames) {
  SnapshotBuffer buffer(4);
  EXPECT_FALSE(buffer.sample(0.0));
  EXPECT_TRUE(buffer.push(frame(1, 0, 0.0, 0.0)));
  EXPECT_TRUE(buffer.push(frame(1, 1, 0.1, 1.0)));
  EXPECT_FALSE(buffer.push(frame(1, 1, 0.1, 1.0))) << "a repeated frame is dropped";
  EXPECT_NEAR(buffer.sample(0.05)->front().pos.x(), 0.5, 1e-12);
  EXPECT_NEAR(buffer.sample(1.0)->front().pos.x(), 1.0, 1e-12) << "past the end: the last frame";
  for (std::uint32_t n = 2; n < 10; ++n) buffer.push(frame(1, n, 0.1 * n, n));
  EXPECT_EQ(buffer.size(), 4u);
  EXPECT_TRUE(buffer.push(frame(2, 0, 0.0, 7.0))) << "a new shot starts over";
  EXPECT_EQ(buffer.size(), 1u);
  EXPECT_FALSE(buffer.push(frame(1, 20, 2.0, 0.0))) << "a late frame of the old shot is dropped";
}

TEST(WireReadTest, StateBecomesTheRulesView) {
  pool_MatchState wire{};
  net::setText(wire.match, "s-1");
  wire.phase = pool_PHASE_ASSIGNED;
  wire.shooter = 1;
  wire.breaker = 0;
  wire.seats[0].group = pool_GROUP_STRIPES;
  wire.seats[1].group = pool_GROUP_SOLIDS;
  wire.ball_in_hand = pool_IN_HAND_ANYWHERE;
  wire.winner = -1;
  wire.game = 8;  // since protocol 4 every state names its game and race
  wire.race_to = 1;
  auto view = net::fromWire(wire);
  ASSERT_TRUE(view) << view.error();
  const rules::GameState game = gameStateOf(*view);
  EXPECT_EQ(game.phase, rules::Phase::Assigned);
  EXPECT_EQ(game.shooter, 1);
  EXPECT_EQ(game.groups[1], rules::Group::Solids);
  EXPECT_EQ(game.ball_in_hand, rules::BallInHand::Anywhere);
}

TEST(WireReadTest, OutOfRangeValuesAreFailuresNotCrashes) {
  pool_MatchState state{};
  net::setRawValue(state.phase, 99);
  EXPECT_FALSE(net::fromWire(state));
  pool_ShotResult result{};
  net::setRawValue(result.end, -3);
  EXPECT_FALSE(net::fromWire(result));
  pool_JoinReply reply{};
  net::setRawValue(reply.outcome, 1234);
  EXPECT_FALSE(net::fromWire(reply));
  pool_MatchInfo info{};
  std::memset(info.match, 'x', sizeof info.match);  // unterminated: read up to the bound
  info.game = 9;
  info.race_to = 3;
  auto entry = net::fromWire(info);
  ASSERT_TRUE(entry);
  EXPECT_EQ(entry->match.size(), sizeof info.match);
  info.game = 11;  // no such game: refused, not guessed
  EXPECT_FALSE(net::fromWire(info));
}

}  // namespace
}  // namespace pool::client::test
