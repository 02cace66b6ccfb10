// A practice table as pure match logic: either seat shoots, undo brings the table back bit for
// bit, again replays the shot exactly, coefficients change one table only, every refused
// practice command changes nothing, and snooker's and three-cushion's practice tables rack their
// own game on their own table.
#include <gtest/gtest.h>

#include <cstring>

#include "match_fixture.h"
#include "protocol/practice_request.h"
#include "rules/placement.h"
#include "server/match_publish.h"
#include "table/rack.h"

namespace pool::server::test {
namespace {

using protocol::PracticeAction;
using protocol::PracticeRequest;

MatchOptions unpaced() {
  MatchOptions o;
  o.unpaced = true;
  return o;
}

protocol::MatchSettings practiceSettings() {
  protocol::MatchSettings s;
  s.practice = true;
  return s;
}

/// A practice table opened by "Ada" (client a) in seat 0.
std::unique_ptr<Match> practiceTable() {
  auto m = std::make_unique<Match>("srv-1", "Table 1", runner(), unpaced(), 42);
  EXPECT_TRUE(m->takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a"), practiceSettings()).accepted());
  return m;
}

PracticeRequest practice(PracticeAction action, std::uint32_t seq, int seat = 0) {
  PracticeRequest r;
  r.match = "srv-1";
  r.seat = seat;
  r.seat_token = seat == 0 ? kToken0 : kToken1;
  r.seq = seq;
  r.action = action;
  protocol::signPractice(r, keyOf(clientOf(seat)));
  return r;
}

protocol::ShotRequest stroke(std::uint32_t seq, int seat = 0, double yaw = 0.0) {
  protocol::ShotRequest r;
  r.match = "srv-1";
  r.seat = seat;
  r.seat_token = seat == 0 ? kToken0 : kToken1;
  r.seq = seq;
  r.cue.yaw = yaw;
  r.cue.speed = 6.0;
  r.cue.tip_side = 0.05;
  return sealed(r);
}

/// Lets the shot in motion land; its report.
ShotReport land(Match& m) {
  m.takeDueFrames(1e9);
  auto report = m.finishShot();
  EXPECT_TRUE(report);
  return report ? *report : ShotReport{};
}

bool sameBits(const std::vector<physics::Ball>& a, const std::vector<physics::Ball>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto same = [](const auto& x, const auto& y) {
      return std::memcmp(x.data(), y.data(), sizeof(double) * x.size()) == 0;
    };
    if (a[i].id != b[i].id || a[i].state != b[i].state || !same(a[i].pos, b[i].pos) ||
        !same(a[i].orient.coeffs(), b[i].orient.coeffs()) || !same(a[i].vel, b[i].vel) ||
        !same(a[i].ang_vel, b[i].ang_vel)) {
      return false;
    }
  }
  return true;
}

TEST(MatchPracticeTest, OnePlayerStartsItAndEitherSeatShootsWithTheCueBallInHand) {
  auto m = practiceTable();
  EXPECT_TRUE(m->practice());
  EXPECT_TRUE(m->inPlay());
  EXPECT_EQ(m->game().ball_in_hand, rules::BallInHand::Anywhere);
  ASSERT_TRUE(m->takeSeat(1, "Bob", "b", kToken1, publicKeyOf("b")).accepted());
  ASSERT_TRUE(m->handleShot(stroke(1, 1), 0.0).accepted());
  land(*m);
  ASSERT_TRUE(m->handleShot(stroke(2, 1, 3.0), 0.0).accepted());  // Bob again: no turns here
  land(*m);
  EXPECT_TRUE(m->handleShot(stroke(1, 0, 1.0), 0.0).accepted());  // and Ada
  land(*m);
  EXPECT_EQ(m->game().ball_in_hand, rules::BallInHand::Anywhere);
  // Leaving forfeits nothing: the other player practises on.
  ASSERT_TRUE(
      m->seatRequest(seatRequest(protocol::JoinAction::Leave, "b", 1, kToken1, 3)).accepted());
  EXPECT_EQ(m->game().winner, -1);
  EXPECT_TRUE(m->inPlay());
}

TEST(MatchPracticeTest, UndoIsBitIdenticalAndAgainReplaysTheShotExactly) {
  auto m = practiceTable();
  const auto before = m->balls();
  ASSERT_TRUE(m->handleShot(stroke(1), 0.0).accepted());
  const ShotReport first = land(*m);
  const auto after = m->balls();
  ASSERT_FALSE(sameBits(before, after));
  EXPECT_EQ(m->undoDepth(), 1u);

  // Again while the last change is that shot: the table before it, the same shot, the same end.
  const CommandAnswer again = m->handlePractice(practice(PracticeAction::Again, 2), 0.0);
  ASSERT_TRUE(again.accepted()) << again.rejection.text;
  ASSERT_TRUE(again.in_motion);
  const ShotReport second = land(*m);
  ASSERT_EQ(second.events.size(), first.events.size());
  for (std::size_t i = 0; i < first.events.size(); ++i) {
    EXPECT_EQ(std::memcmp(&second.events[i].t, &first.events[i].t, sizeof(double)), 0) << i;
  }
  EXPECT_TRUE(sameBits(m->balls(), after));
  EXPECT_EQ(m->undoDepth(), 1u);

  const auto revision = m->revision();
  const CommandAnswer undo = m->handlePractice(practice(PracticeAction::Undo, 3), 0.0);
  ASSERT_TRUE(undo.accepted()) << undo.rejection.text;
  ASSERT_TRUE(undo.done);
  EXPECT_TRUE(sameBits(m->balls(), before));
  EXPECT_GT(m->revision(), revision);

  // Nothing left to undo, no shot to play again: refused, nothing changed, the numbers used up.
  const auto settled = m->revision();
  const CommandAnswer none = m->handlePractice(practice(PracticeAction::Undo, 4), 0.0);
  EXPECT_EQ(none.rejection.reason, Reject::BadPractice);
  const CommandAnswer no_shot = m->handlePractice(practice(PracticeAction::Again, 5), 0.0);
  EXPECT_EQ(no_shot.rejection.reason, Reject::BadPractice);
  EXPECT_EQ(m->revision(), settled);
  EXPECT_TRUE(sameBits(m->balls(), before));
  EXPECT_EQ(m->handlePractice(practice(PracticeAction::Undo, 5), 0.0).rejection.reason,
            Reject::StaleSequence);
}

TEST(MatchPracticeTest, RefusedCommandsChangeNothing) {
  auto m = practiceTable();
  const auto before = m->balls();
  const auto revision = m->revision();
  PracticeRequest forged = practice(PracticeAction::Rack, 1);
  forged.rack = 9;  // changed after signing
  EXPECT_EQ(m->handlePractice(forged, 0.0).rejection.reason, Reject::BadSignature);
  PracticeRequest unsigned_copy = practice(PracticeAction::Undo, 1);
  unsigned_copy.signature.clear();
  EXPECT_EQ(m->handlePractice(unsigned_copy, 0.0).rejection.reason, Reject::Unsigned);
  PracticeRequest wrong = practice(PracticeAction::Undo, 1);
  wrong.seat_token = kToken1;
  EXPECT_EQ(m->handlePractice(wrong, 0.0).rejection.reason, Reject::BadToken);
  EXPECT_EQ(m->handlePractice(practice(PracticeAction::Undo, 1, 1), 0.0).rejection.reason,
            Reject::WrongSeat);  // nobody in seat 1
  PracticeRequest overlap = practice(PracticeAction::Layout, 2);
  overlap.balls = {{0, 0.0, 0.0}, {5, 0.03, 0.0}};
  protocol::signPractice(overlap, keyOf("a"));
  EXPECT_EQ(m->handlePractice(overlap, 0.0).rejection.reason, Reject::BadPractice);
  PracticeRequest pocket = practice(PracticeAction::Layout, 3);
  pocket.balls = {{0, 1.27, 0.635}};  // over the corner pocket
  protocol::signPractice(pocket, keyOf("a"));
  EXPECT_EQ(m->handlePractice(pocket, 0.0).rejection.reason, Reject::BadPractice);
  PracticeRequest physics = practice(PracticeAction::Physics, 4);
  physics.coefficients = protocol::coefficientsOf(m->table().spec.params);
  physics.coefficients[3] = 1.5;  // e_b above 1
  protocol::signPractice(physics, keyOf("a"));
  const CommandAnswer bad = m->handlePractice(physics, 0.0);
  EXPECT_EQ(bad.rejection.reason, Reject::BadPractice);
  EXPECT_NE(bad.rejection.text.find("e_b"), std::string::npos) << bad.rejection.text;
  EXPECT_TRUE(m->standardPhysics());
  EXPECT_EQ(m->revision(), revision);
  EXPECT_TRUE(sameBits(m->balls(), before));
  EXPECT_EQ(m->undoDepth(), 0u);

  // While a shot is in motion nothing else goes.
  ASSERT_TRUE(m->handleShot(stroke(5), 0.0).accepted());
  EXPECT_EQ(m->handlePractice(practice(PracticeAction::Undo, 6), 0.0).rejection.reason,
            Reject::BallsMoving);
}

TEST(MatchPracticeTest, CommandsAtAMatchAreRefusedAsNotPractice) {
  auto m = seatedMatch();
  const auto revision = m->revision();
  const CommandAnswer answer = m->handlePractice(practice(PracticeAction::Undo, 1), 0.0);
  EXPECT_EQ(answer.rejection.reason, Reject::NotPractice);
  EXPECT_EQ(m->revision(), revision);
  // Its signature checked out: its number is used up, a replay is stale.
  EXPECT_EQ(m->handlePractice(practice(PracticeAction::Undo, 1), 0.0).rejection.reason,
            Reject::StaleSequence);
}

TEST(MatchPracticeTest, CoefficientsChangeThatTableOnly) {
  auto slow = practiceTable();
  auto standard = practiceTable();
  PracticeRequest physics = practice(PracticeAction::Physics, 1);
  physics.coefficients = protocol::coefficientsOf(slow->table().spec.params);
  physics.coefficients[1] = 0.03;  // u_r: three times the rolling resistance
  protocol::signPractice(physics, keyOf("a"));
  ASSERT_TRUE(slow->handlePractice(physics, 0.0).accepted());
  EXPECT_FALSE(slow->standardPhysics());
  EXPECT_TRUE(standard->standardPhysics());
  EXPECT_EQ(slow->table().spec.params.u_r, 0.03);
  EXPECT_EQ(standard->table().spec.params.u_r, nineFoot()->spec.params.u_r);

  // The cue ball alone on each table, rolling up and down it.
  for (Match* m : {slow.get(), standard.get()}) {
    PracticeRequest clear = practice(PracticeAction::Rack, 2);
    clear.rack = 0;
    protocol::signPractice(clear, keyOf("a"));
    ASSERT_TRUE(m->handlePractice(clear, 0.0).accepted());
  }
  const CommandAnswer on_slow = slow->handleShot(stroke(3, 0, 3.1), 0.0);
  ASSERT_TRUE(on_slow.accepted()) << on_slow.rejection.text;
  const CommandAnswer on_standard = standard->handleShot(stroke(3, 0, 3.1), 0.0);
  ASSERT_TRUE(on_standard.accepted()) << on_standard.rejection.text;
  const ShotReport a = land(*slow);
  const ShotReport b = land(*standard);
  ASSERT_FALSE(a.events.empty());
  EXPECT_LT(a.events.back().t, b.events.back().t);  // the balls stop sooner

  // Back to the standard values: a standard table again.
  physics.seq = 4;
  physics.coefficients = protocol::coefficientsOf(nineFoot()->spec.params);
  protocol::signPractice(physics, keyOf("a"));
  ASSERT_TRUE(slow->handlePractice(physics, 0.0).accepted());
  EXPECT_TRUE(slow->standardPhysics());
}

TEST(MatchPracticeTest, AnyBallOfARackedTableMovesToAFreeSpot) {
  // What the window sends when a ball is dragged: every ball where the state shows it, one moved.
  auto m = practiceTable();
  ASSERT_TRUE(m->handleShot(stroke(1), 0.0).accepted());  // the break: balls at rest anywhere
  land(*m);
  PracticeRequest layout = practice(PracticeAction::Layout, 2);
  for (const auto& b : m->balls()) {
    if (!physics::onTable(b.state)) continue;
    if (b.id == 8) continue;
    layout.balls.push_back({b.id, b.pos.x(), b.pos.y()});
  }
  // The 8 (wherever it went) to a spot no ball covers: the head string's far end.
  layout.balls.push_back({8, -0.635, 0.6});
  for (const auto& b : m->balls()) {
    ASSERT_GT((b.pos.head<2>() - Eigen::Vector2d(-0.635, 0.6)).norm(), 0.06) << "ball " << b.id;
  }
  protocol::signPractice(layout, keyOf("a"));
  const CommandAnswer moved = m->handlePractice(layout, 0.0);
  ASSERT_TRUE(moved.accepted()) << moved.rejection.text;
  for (const auto& b : m->balls()) {
    if (b.id == 8) {
      EXPECT_EQ(b.pos.head<2>(), Eigen::Vector2d(-0.635, 0.6));
    }
  }
  // And a frozen rack as laid out, one ball dragged off it.
  auto fresh = practiceTable();
  PracticeRequest rack_layout = practice(PracticeAction::Layout, 1);
  for (const auto& b : fresh->balls()) {
    rack_layout.balls.push_back({b.id, b.pos.x(), b.pos.y()});
    if (b.id == 5) rack_layout.balls.back() = {5, 0.0, -0.4};
  }
  protocol::signPractice(rack_layout, keyOf("a"));
  const CommandAnswer dragged = fresh->handlePractice(rack_layout, 0.0);
  EXPECT_TRUE(dragged.accepted()) << dragged.rejection.text;
}

TEST(MatchPracticeTest, RacksAndClearingAreUndone) {
  auto m = practiceTable();
  const auto eight = m->balls();
  PracticeRequest rack = practice(PracticeAction::Rack, 1);
  rack.rack = 10;
  protocol::signPractice(rack, keyOf("a"));
  ASSERT_TRUE(m->handlePractice(rack, 0.0).accepted());
  EXPECT_EQ(m->balls().size(), 11u);
  EXPECT_EQ(m->settings().game, rules::Game::TenBall);
  rack.rack = 0;
  rack.seq = 2;
  protocol::signPractice(rack, keyOf("a"));
  ASSERT_TRUE(m->handlePractice(rack, 0.0).accepted());
  ASSERT_EQ(m->balls().size(), 1u);
  EXPECT_EQ(m->balls()[0].id, physics::kCueBall);
  ASSERT_TRUE(m->handlePractice(practice(PracticeAction::Undo, 3), 0.0).accepted());
  EXPECT_EQ(m->balls().size(), 11u);
  ASSERT_TRUE(m->handlePractice(practice(PracticeAction::Undo, 4), 0.0).accepted());
  EXPECT_TRUE(sameBits(m->balls(), eight));
}

/// A practice table of `game` opened by "Ada" in seat 0, at a server with a table for each game.
std::unique_ptr<Match> practiceTableOf(rules::Game game) {
  MatchOptions options = unpaced();
  options.tables = std::make_shared<TableRunners>(runner());
  auto m = std::make_unique<Match>("srv-1", "Table 1", runner(), options, 42);
  protocol::MatchSettings settings = practiceSettings();
  settings.game = game;
  EXPECT_TRUE(m->takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a"), settings).accepted());
  return m;
}

/// Seat 0's Rack command of game number `number` (0: clear), signed.
PracticeRequest rackOf(int number, std::uint32_t seq) {
  PracticeRequest r = practice(PracticeAction::Rack, seq);
  r.rack = number;
  protocol::signPractice(r, keyOf("a"));
  return r;
}

/// Seat 0's Layout command of `balls`, signed.
PracticeRequest layoutOf(const std::vector<protocol::BallSpot>& balls, std::uint32_t seq) {
  PracticeRequest r = practice(PracticeAction::Layout, seq);
  r.balls = balls;
  protocol::signPractice(r, keyOf("a"));
  return r;
}

/// `command` is refused as bad_practice with `text`, and the table, its game and its undo are
/// as they were.
void expectRefusedAndNothingChanged(Match& m, const PracticeRequest& command,
                                    const std::string& text) {
  const auto balls = m.balls();
  const auto revision = m.revision();
  const auto undo = m.undoDepth();
  const auto game = m.settings().game;
  const std::string table = m.table().spec.name;
  const CommandAnswer answer = m.handlePractice(command, 0.0);
  EXPECT_EQ(answer.rejection.reason, Reject::BadPractice);
  EXPECT_EQ(answer.rejection.text, text);
  EXPECT_TRUE(sameBits(m.balls(), balls));
  EXPECT_EQ(m.revision(), revision);
  EXPECT_EQ(m.undoDepth(), undo);
  EXPECT_EQ(m.settings().game, game);
  EXPECT_EQ(m.table().spec.name, table);
}

TEST(MatchPracticeTest, ASnookerPracticeTableRacksSnookerOnItsOwnTable) {
  auto m = practiceTableOf(rules::Game::Snooker);
  EXPECT_TRUE(m->practice());
  EXPECT_TRUE(m->inPlay());
  EXPECT_EQ(m->table().spec.name, "snooker-12ft");
  EXPECT_EQ(m->settings().game, rules::Game::Snooker);
  EXPECT_EQ(m->game().ball_in_hand, rules::BallInHand::Anywhere);
  EXPECT_EQ(m->lastVerdict(), "practice: snooker rack");

  // The rack of a snooker match (Section 2, "Position of Balls"), as table::snookerRack lays it
  // out with a hand rack's gaps: the colours on their spots, the cue ball in the D, each red
  // within a hand rack's stray of its slot.
  const auto& table = m->table();
  const double r = table.context.ball_radius;
  const auto slots = table::snookerRack(table.spec, r, 2.0 * table::kRackStray);
  ASSERT_EQ(slots.size(), 22u);
  ASSERT_EQ(m->balls().size(), 22u);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const physics::Ball& b = m->balls()[i];
    ASSERT_EQ(b.id, slots[i].id);
    EXPECT_EQ(b.state, physics::MotionState::Stationary);
    EXPECT_EQ(b.pos.z(), r);
    const double off = (b.pos.head<2>() - slots[i].pos).norm();
    if (b.id == physics::kCueBall || b.id > table::kSnookerReds) {
      EXPECT_EQ(off, 0.0) << "ball " << b.id;
    } else {
      EXPECT_LE(off, table::kRackStray * (1 + 1e-9)) << "red " << b.id;
    }
  }
  const physics::Ball& cue = m->balls().front();
  std::vector<physics::Ball> others(m->balls().begin() + 1, m->balls().end());
  EXPECT_TRUE(rules::checkCueBallPlacement(rules::BallInHand::InTheD, cue.pos.head<2>(), others,
                                           table.context)
                  .ok());
  // The publishd state: 22 balls, the cue ball struck.
  const protocol::MatchView view = matchViewOf(*m);
  EXPECT_EQ(view.balls.size(), 22u);
  EXPECT_EQ(view.cue_ball, physics::kCueBall);
}

TEST(MatchPracticeTest, ASnookerPracticeTableLaysOutTheBlackAndRefusesOtherGamesAndBalls) {
  auto m = practiceTableOf(rules::Game::Snooker);
  // Every ball where it lies and the black moved, as a drag sends it.
  const Eigen::Vector2d black_to(1.2, 0.5);
  std::vector<protocol::BallSpot> spots;
  for (const auto& b : m->balls()) {
    if (b.id == table::kSnookerBlack) {
      spots.push_back({b.id, black_to.x(), black_to.y()});
    } else {
      spots.push_back({b.id, b.pos.x(), b.pos.y()});
    }
  }
  const CommandAnswer laid = m->handlePractice(layoutOf(spots, 1), 0.0);
  ASSERT_TRUE(laid.accepted()) << laid.rejection.text;
  ASSERT_EQ(m->balls().size(), 22u);
  EXPECT_EQ(m->balls().back().id, table::kSnookerBlack);
  EXPECT_EQ(m->balls().back().pos.head<2>(), black_to);

  // A 23rd ball, an 8-ball rack, a number no game has: each refused in one line, nothing
  // changed.
  spots.push_back({22, 0.0, -0.6});
  expectRefusedAndNothingChanged(*m, layoutOf(spots, 2), "layout: ball 22: not a ball id (0-21)");
  expectRefusedAndNothingChanged(
      *m, rackOf(8, 3), "rack: this is a snooker table; it racks 22 (snooker) or 0 (clear)");
  expectRefusedAndNothingChanged(
      *m, rackOf(7, 4),
      "rack: 7 is no game's number; this is a snooker table; it racks 22 (snooker) or 0 (clear)");

  // Snooker again, then the cue ball alone; each undone.
  ASSERT_TRUE(m->handlePractice(rackOf(22, 5), 0.0).accepted());
  EXPECT_EQ(m->balls().size(), 22u);
  EXPECT_EQ(m->balls().back().pos.head<2>(),
            *table::snookerSpotOf(m->table().spec, table::kSnookerBlack));
  ASSERT_TRUE(m->handlePractice(rackOf(0, 6), 0.0).accepted());
  ASSERT_EQ(m->balls().size(), 1u);
  EXPECT_EQ(m->balls()[0].id, physics::kCueBall);
  EXPECT_EQ(m->settings().game, rules::Game::Snooker);
  ASSERT_TRUE(m->handlePractice(practice(PracticeAction::Undo, 7), 0.0).accepted());
  ASSERT_TRUE(m->handlePractice(practice(PracticeAction::Undo, 8), 0.0).accepted());
  EXPECT_EQ(m->balls().back().pos.head<2>(), black_to);

  // A shot: from the cue ball as it lies, struck by either seat.
  const CommandAnswer shot = m->handleShot(stroke(9), 0.0);
  ASSERT_TRUE(shot.accepted()) << shot.rejection.text;
  const ShotReport report = land(*m);
  ASSERT_FALSE(report.events.empty());
  EXPECT_EQ(report.events.front().ball_a, physics::kCueBall);
  EXPECT_TRUE(report.verdict.legal());
  EXPECT_EQ(m->game().ball_in_hand, rules::BallInHand::Anywhere);
}

TEST(MatchPracticeTest, AThreeCushionPracticeTableRacksItsOpeningAndTheWhiteIsStruck) {
  auto m = practiceTableOf(rules::Game::ThreeCushion);
  EXPECT_EQ(m->table().spec.name, "carom-match");
  EXPECT_EQ(m->settings().game, rules::Game::ThreeCushion);
  // The opening (UMB, starting position): the red on the top spot, the yellow on the bottom
  // spot, the white beside it on the head string.
  const table::Spots spots = table::spotsFor(m->table().spec);
  ASSERT_EQ(m->balls().size(), 3u);
  EXPECT_EQ(m->balls()[rules::kCaromRed].pos.head<2>(), spots.foot_spot);
  EXPECT_EQ(m->balls()[rules::kCaromYellow].pos.head<2>(), spots.head_spot);
  const Eigen::Vector2d white = m->balls()[rules::kCaromWhite].pos.head<2>();
  EXPECT_EQ(white.x(), spots.head_spot.x());
  EXPECT_NEAR(std::abs(white.y() - spots.head_spot.y()), table::kCaromBreakOffset, 1e-12);
  EXPECT_EQ(matchViewOf(*m).cue_ball, rules::kCaromWhite);

  expectRefusedAndNothingChanged(*m, layoutOf({{0, -0.5, 0.0}, {3, 0.5, 0.0}}, 1),
                                 "layout: ball 3: not a ball id (0-2)");
  expectRefusedAndNothingChanged(
      *m, rackOf(9, 2),
      "rack: this is a three-cushion table; it racks 3 (three-cushion) or 0 (clear)");

  // Seat 0, then seat 1, each strikes the white: the practice rules judge the white's shot.
  ASSERT_TRUE(m->takeSeat(1, "Bob", "b", kToken1, publicKeyOf("b")).accepted());
  for (int seat : {0, 1}) {
    const Eigen::Vector2d from = m->balls()[rules::kCaromWhite].pos.head<2>();
    const Eigen::Vector2d to = m->balls()[rules::kCaromRed].pos.head<2>() - from;
    const CommandAnswer shot = m->handleShot(
        stroke(static_cast<std::uint32_t>(3 + seat), seat, std::atan2(to.y(), to.x())), 0.0);
    ASSERT_TRUE(shot.accepted()) << shot.rejection.text;
    const ShotReport report = land(*m);
    ASSERT_FALSE(report.events.empty());
    EXPECT_EQ(report.events.front().ball_a, rules::kCaromWhite) << "seat " << seat;
    EXPECT_TRUE(report.verdict.legal());
    EXPECT_EQ(matchViewOf(*m).cue_ball, rules::kCaromWhite);
  }
  ASSERT_TRUE(m->handlePractice(rackOf(3, 5), 0.0).accepted());
  EXPECT_EQ(m->balls().size(), 3u);
  EXPECT_EQ(m->balls()[rules::kCaromRed].pos.head<2>(), spots.foot_spot);
}

TEST(MatchPracticeTest, APoolPracticeTableRacksThePoolGamesOnly) {
  auto m = practiceTableOf(rules::Game::NineBall);
  EXPECT_EQ(m->table().spec.name, "wpa-9ft");
  expectRefusedAndNothingChanged(*m, rackOf(22, 1),
                                 "rack: this is a pool table; it racks 8, 9, 10 or 0 (clear)");
  expectRefusedAndNothingChanged(*m, rackOf(3, 2),
                                 "rack: this is a pool table; it racks 8, 9, 10 or 0 (clear)");
  expectRefusedAndNothingChanged(*m, layoutOf({{0, -0.5, 0.0}, {16, 0.5, 0.0}}, 3),
                                 "layout: ball 16: not a ball id (0-15)");
  ASSERT_TRUE(m->handlePractice(rackOf(8, 4), 0.0).accepted());
  EXPECT_EQ(m->settings().game, rules::Game::EightBall);
  EXPECT_EQ(m->balls().size(), 16u);
}

}  // namespace
}  // namespace pool::server::test
