// A three-cushion match on the server, without DDS: the opener's choice moves the match onto the
// carom table, each player strikes their own ball, points and innings land in the match view, and
// the points setting is signed with the seat request.
#include <gtest/gtest.h>

#include <cmath>

#include "match_fixture.h"
#include "rules/three_cushion.h"
#include "server/match/match.h"
#include "server/match_publish.h"

namespace pool::server::test {
namespace {

protocol::MatchSettings threeCushion(int points) {
  protocol::MatchSettings s;
  s.game = rules::Game::ThreeCushion;
  s.points = points;
  return s;
}

MatchOptions withTables() {
  MatchOptions options = pacedOptions();
  options.tables = std::make_shared<TableRunners>(runner());
  return options;
}

/// A soft stroke by `seat` straight at the red from its own ball (no point: one ball, no
/// cushions before it).
protocol::ShotRequest atTheRed(const Match& m, int seat, std::uint32_t seq) {
  const int own = rules::caromBallOf(m.game(), seat);
  Eigen::Vector2d from, red;
  for (const auto& b : m.balls()) {
    if (b.id == own) from = b.pos.head<2>();
    if (b.id == rules::kCaromRed) red = b.pos.head<2>();
  }
  protocol::ShotRequest r;
  r.match = "srv-1";
  r.seat = seat;
  r.seat_token = seat == 0 ? kToken0 : kToken1;
  r.seq = seq;
  const Eigen::Vector2d d = red - from;
  r.cue.yaw = std::atan2(d.y(), d.x());
  r.cue.speed = 1.5;
  return sealed(r);
}

TEST(ThreeCushionMatch, TheOpenersChoiceMovesTheMatchOntoTheCaromTable) {
  Match m("srv-1", "Table 1", runner(), withTables(), 42);
  EXPECT_EQ(m.table().spec.name, "wpa-9ft");
  ASSERT_TRUE(m.takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a"), threeCushion(3)).accepted());
  ASSERT_TRUE(m.takeSeat(1, "Bob", "b", kToken1, publicKeyOf("b")).accepted());
  EXPECT_EQ(m.table().spec.name, "carom-match");
  EXPECT_FALSE(m.table().spec.pockets);
  EXPECT_EQ(m.rules().game, rules::Game::ThreeCushion);
  EXPECT_EQ(m.rules().three_cushion.points_to, 3);
  // The opening (UMB): three balls on their spots, sized for the carom table.
  ASSERT_EQ(m.balls().size(), 3u);
  for (const auto& b : m.balls()) EXPECT_NEAR(b.pos.z(), 0.03075, 1e-12);
  EXPECT_EQ(lobbyEntryOf(m, "srv").table, "carom-match");
}

TEST(ThreeCushionMatch, EachPlayerStrikesTheirOwnBall) {
  Match m("srv-1", "Table 1", runner(), withTables(), 42);
  ASSERT_TRUE(m.takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a"), threeCushion(3)).accepted());
  ASSERT_TRUE(m.takeSeat(1, "Bob", "b", kToken1, publicKeyOf("b")).accepted());
  const int breaker = m.game().breaker;
  const int other = 1 - breaker;
  // The breaker plays the white at the red: a legal opening, no point, the inning ends.
  const CommandAnswer first = m.handleShot(atTheRed(m, breaker, 1), 0.0);
  ASSERT_TRUE(first.accepted()) << first.rejection.text;
  auto report = finishNow(m);
  ASSERT_TRUE(report);
  ASSERT_FALSE(report->events.empty());
  EXPECT_EQ(report->events.front().ball_a, rules::kCaromWhite);
  EXPECT_TRUE(report->verdict.legal()) << rules::describe(report->verdict);
  EXPECT_EQ(m.game().shooter, other);
  EXPECT_EQ(m.game().innings[static_cast<std::size_t>(breaker)], 1);
  // The other player strikes the yellow.
  ASSERT_TRUE(m.handleShot(atTheRed(m, other, 1), 100.0).accepted());
  report = finishNow(m, 2e6);
  ASSERT_TRUE(report);
  EXPECT_EQ(report->events.front().ball_a, rules::kCaromYellow);
  // The match view says whose ball it is now and the innings.
  const protocol::MatchView view = matchViewOf(m, std::nullopt);
  EXPECT_EQ(view.cue_ball, rules::kCaromWhite);
  EXPECT_EQ(view.seats[static_cast<std::size_t>(breaker)].innings, 1);
  EXPECT_EQ(view.seats[static_cast<std::size_t>(other)].innings, 1);
  EXPECT_EQ(view.settings.points, 3);
}

TEST(ThreeCushionMatch, ThePointsAreSignedWithTheSeatRequest) {
  protocol::SeatRequest r = seatRequest(protocol::JoinAction::Seat, "a", 0, 0, 1);
  r.settings = threeCushion(10);
  protocol::signSeatRequest(r, keyOf("a"));
  EXPECT_EQ(protocol::verifySeatRequest(r, publicKeyOf("a")), protocol::SignatureCheck::Valid);
  r.settings->points = 1;  // a game shortened in flight no longer verifies
  EXPECT_EQ(protocol::verifySeatRequest(r, publicKeyOf("a")),
            protocol::SignatureCheck::BadSignature);
  EXPECT_FALSE(protocol::checkSettings(threeCushion(0)).ok());
  EXPECT_FALSE(protocol::checkSettings(threeCushion(101)).ok());
}

}  // namespace
}  // namespace pool::server::test
