// Snooker on built logs, clause by clause after the WPBSA's Official Rules of Snooker (Section 2,
// "Position of Balls"; Section 3, the game: "Play", "Playing from in-Hand", "Spotting Colours",
// "Touching Ball", "Snookered after a Foul" (the free ball), "Fouls" and their penalties, "Foul
// and a Miss", "Stalemate"). Positions are exact (no tolerance) unless a test says otherwise.
#include <gtest/gtest.h>

#include <algorithm>

#include "rules/fixture.h"
#include "rules/game_rules.h"
#include "rules/placement.h"
#include "rules/real_play.h"
#include "rules/snooker.h"
#include "table/rack.h"

namespace pool::rules {
namespace {

using table::kSnookerBlack;
using table::kSnookerBlue;
using table::kSnookerBrown;
using table::kSnookerGreen;
using table::kSnookerPink;
using table::kSnookerYellow;
using test::LogBuilder;
using test::makeShot;
using Vec2 = Eigen::Vector2d;

constexpr double kSnookerR = 0.02625;  // a snooker ball's radius (52.5 mm across)

const TableContext& snookerTable() {
  static const TableContext context = [] {
    auto spec = table::loadTableSpec("snooker-12ft");
    EXPECT_TRUE(spec) << spec.error();
    return tableContext(*spec);
  }();
  return context;
}

Eigen::Vector2d colourSpot(int colour) {
  return *table::snookerSpotOf(snookerTable().spec, colour);
}

physics::Ball snookerBall(int id, double x, double y) {
  return physics::restingBall(id, Eigen::Vector2d(x, y), kSnookerR);
}

physics::Ball onItsSpot(int colour) {
  return physics::restingBall(colour, colourSpot(colour), kSnookerR);
}

/// The six colours on their spots, the cue ball at (cue_x, cue_y) and the given reds, each red in
/// a row across the top half of the table, well apart.
std::vector<physics::Ball> snookerLayout(int reds, double cue_x = -0.6, double cue_y = -0.4) {
  std::vector<physics::Ball> balls{snookerBall(0, cue_x, cue_y)};
  for (int i = 1; i <= reds; ++i) balls.push_back(snookerBall(i, 0.3 + 0.1 * i, 0.6));
  for (int c = kSnookerYellow; c <= kSnookerBlack; ++c) balls.push_back(onItsSpot(c));
  return balls;
}

GameState snookerInPlay(int shooter, int ball_on = kOnRed) {
  GameState s = newFrame(0);
  s.phase = Phase::Open;
  s.ball_in_hand = BallInHand::None;
  s.shooter = shooter;
  s.ball_on = ball_on;
  return s;
}

Verdict snookerJudged(const GameState& state, const Shot& shot) {
  auto v = judgeSnooker(state, shot, snookerTable(), SnookerConfig{});
  EXPECT_TRUE(v) << v.error();
  return v ? *v : Verdict{};
}

bool snookerOffers(const Verdict& v, Choice c) {
  return std::find(v.options.begin(), v.options.end(), c) != v.options.end();
}

Eigen::Vector2d respotPos(const Verdict& v, int id) {
  for (const Respot& r : v.respots) {
    if (r.id == id) return r.pos;
  }
  ADD_FAILURE() << "ball " << id << " not re-spotted: " << describe(v);
  return Eigen::Vector2d::Constant(99.0);
}

Intent nominated(int colour) {
  Intent i;
  i.ball = colour;
  return i;
}

// ---- Section 2, "Position of Balls"; Section 3, "Playing from in-Hand".

TEST(SnookerRack, RedsBehindThePinkAndColoursOnTheirSpots) {
  const TableContext& t = snookerTable();
  const auto rack = table::snookerRack(t.spec, kSnookerR);
  ASSERT_EQ(rack.size(), 22u);
  double apex_x = 1e9;
  for (const auto& b : rack) {
    if (isRed(b.id)) apex_x = std::min(apex_x, b.pos.x());
    if (isColour(b.id)) {
      EXPECT_EQ(b.pos, colourSpot(b.id)) << b.id;
    }
  }
  // "the apex red as near to the Pink as possible without touching it": 1 mm, to 1e-12 m.
  EXPECT_NEAR(apex_x - colourSpot(kSnookerPink).x(), 2.0 * kSnookerR + table::kSnookerApexGap,
              1e-12);
  for (std::size_t i = 0; i < rack.size(); ++i) {
    for (std::size_t j = i + 1; j < rack.size(); ++j)
      EXPECT_GE((rack[i].pos - rack[j].pos).norm(), 2.0 * kSnookerR - 1e-12) << i << " " << j;
  }
  EXPECT_TRUE(table::inTheD(*t.snooker, rack[0].pos));  // the cue ball waits in the D
  // Hand racking moves the reds only.
  const auto hand =
      table::rackFor(table::RackType::Snooker, t.spec, kSnookerR, 7, table::RackGenerator::Hand);
  for (const auto& b : hand) {
    if (!isRed(b.id)) {
      const auto frozen =
          std::find_if(rack.begin(), rack.end(), [&](const auto& f) { return f.id == b.id; });
      EXPECT_EQ(b.pos, frozen->pos) << b.id;
    }
  }
}

TEST(SnookerPlacement, TheCueBallInHandGoesInTheD) {
  const TableContext& t = snookerTable();
  const auto balls = snookerLayout(3);
  const Eigen::Vector2d brown = colourSpot(kSnookerBrown);
  EXPECT_TRUE(
      checkCueBallPlacement(BallInHand::InTheD, brown + Eigen::Vector2d(-0.1, 0.1), balls, t).ok());
  // Outside the D's semicircle, and in front of the baulk line.
  EXPECT_EQ(checkCueBallPlacement(BallInHand::InTheD, brown + Eigen::Vector2d(-0.2, 0.25), balls, t)
                .code(),
            PlacementProblem::NotInTheD);
  EXPECT_EQ(checkCueBallPlacement(BallInHand::InTheD, brown + Eigen::Vector2d(0.01, 0.1), balls, t)
                .code(),
            PlacementProblem::NotInTheD);
  // A pool table has no D.
  EXPECT_EQ(
      checkCueBallPlacement(BallInHand::InTheD, Eigen::Vector2d(-0.8, 0.0), balls, test::nineFoot())
          .code(),
      PlacementProblem::NotInTheD);
}

// ---- Section 3, "Play": a red, then a colour, while reds remain; then the colours in order.

TEST(SnookerPlay, ARedScoresOneAndTheColourIsOnNext) {
  const Shot shot = makeShot(snookerLayout(3), Intent::none(),
                             LogBuilder().hit(0, 1).pocket(1, "foot_left_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.scored, 1);
  EXPECT_TRUE(v.turn_continues);
  EXPECT_EQ(v.next.ball_on, kOnColour);
  EXPECT_EQ(v.next.points, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(v.next.run, 1);
  EXPECT_TRUE(v.respots.empty());  // reds are never re-spotted
}

TEST(SnookerPlay, TwoRedsInOneStrokeScoreTwo) {
  const Shot shot = makeShot(snookerLayout(3), Intent::none(),
                             LogBuilder()
                                 .hit(0, 1)
                                 .hit(1, 2)
                                 .pocket(1, "foot_left_corner")
                                 .pocket(2, "foot_right_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.scored, 2);
}

TEST(SnookerPlay, ANominatedColourScoresItsValueAndIsRespotted) {
  auto balls = snookerLayout(3);
  balls[1].state = physics::MotionState::Pocketed;  // the red just potted
  const Shot shot = makeShot(balls, nominated(kSnookerBlue),
                             LogBuilder().hit(0, kSnookerBlue).pocket(kSnookerBlue, "left_side"));
  GameState s = snookerInPlay(1, kOnColour);
  s.points = {10, 1};
  s.run = 1;
  const Verdict v = snookerJudged(s, shot);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.scored, 5);  // Section 2: the blue is worth 5
  EXPECT_EQ(v.next.points, (std::array<int, 2>{10, 6}));
  EXPECT_EQ(v.next.run, 6);
  EXPECT_EQ(v.next.high_run[1], 6);
  EXPECT_EQ(respotPos(v, kSnookerBlue), colourSpot(kSnookerBlue));  // "Spotting Colours"
  EXPECT_EQ(v.next.ball_on, kOnRed);
}

TEST(SnookerPlay, AnUnnominatedColourIsTheOneTheCueBallHitsFirst) {
  const Shot shot =
      makeShot(snookerLayout(3), Intent::none(),
               LogBuilder().hit(0, kSnookerPink).pocket(kSnookerPink, "foot_left_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0, kOnColour), shot);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.scored, 6);
}

TEST(SnookerPlay, NoScoreEndsTheBreakAndTheOpponentIsOnARed) {
  GameState s = snookerInPlay(0, kOnColour);
  s.run = 9;
  const Shot shot = makeShot(snookerLayout(3), Intent::none(),
                             LogBuilder().hit(0, kSnookerBlack).cushion(kSnookerBlack));
  const Verdict v = snookerJudged(s, shot);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.next.shooter, 1);
  EXPECT_EQ(v.next.run, 0);
  EXPECT_EQ(v.next.ball_on, kOnRed);
  EXPECT_TRUE(v.options.empty());
}

TEST(SnookerPlay, AfterTheLastRedAColourThenTheColoursInOrder) {
  // The last red down: a colour of choice follows, re-spotted; then the yellow is on.
  const Shot red = makeShot(snookerLayout(1), Intent::none(),
                            LogBuilder().hit(0, 1).pocket(1, "foot_left_corner"));
  const Verdict after_red = snookerJudged(snookerInPlay(0), red);
  EXPECT_EQ(after_red.next.ball_on, kOnColour);
  auto balls = snookerLayout(1);
  balls[1].state = physics::MotionState::Pocketed;
  const Shot colour =
      makeShot(balls, nominated(kSnookerBlack),
               LogBuilder().hit(0, kSnookerBlack).pocket(kSnookerBlack, "foot_left_corner"));
  const Verdict v = snookerJudged(after_red.next, colour);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(respotPos(v, kSnookerBlack), colourSpot(kSnookerBlack));
  EXPECT_EQ(v.next.ball_on, kSnookerYellow);
  // In the clearance a potted colour stays down and the next is on.
  const Shot yellow =
      makeShot(balls, Intent::none(),
               LogBuilder().hit(0, kSnookerYellow).pocket(kSnookerYellow, "head_right_corner"));
  const Verdict y = snookerJudged(v.next, yellow);
  EXPECT_TRUE(y.legal()) << describe(y);
  EXPECT_EQ(y.scored, 2);
  EXPECT_TRUE(y.respots.empty());
  EXPECT_EQ(y.next.ball_on, kSnookerGreen);
}

// ---- Section 3, "Fouls": the penalty is the value of the ball on, or of a higher ball involved,
// at least 4; the opponent may play or have the offender play again.

TEST(SnookerFoul, AColourPottedWithTheRedCostsItsValue) {
  const Shot shot = makeShot(snookerLayout(3), Intent::none(),
                             LogBuilder()
                                 .hit(0, 1)
                                 .hit(1, kSnookerPink)
                                 .pocket(1, "foot_left_corner")
                                 .pocket(kSnookerPink, "foot_right_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::BallNotOnPocketed)) << describe(v);
  EXPECT_EQ(v.penalty, 6);
  EXPECT_EQ(v.scored, 0);  // nothing scores on a foul
  EXPECT_EQ(v.next.points, (std::array<int, 2>{0, 6}));
  EXPECT_EQ(respotPos(v, kSnookerPink), colourSpot(kSnookerPink));
  EXPECT_EQ(v.next.shooter, 1);
  EXPECT_TRUE(snookerOffers(v, Choice::PlayOn));
  EXPECT_TRUE(snookerOffers(v, Choice::PassBack));
  EXPECT_FALSE(v.miss);  // the cue ball hit a ball on first
}

TEST(SnookerFoul, HittingTheBlackFirstWhenOnARedCostsSeven) {
  auto balls = snookerLayout(3, 1.2, 0.0);  // the cue ball just short of the black
  const Shot shot = makeShot(balls, Intent::none(), LogBuilder().hit(0, kSnookerBlack));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst)) << describe(v);
  EXPECT_EQ(v.penalty, 7);
}

TEST(SnookerFoul, AnInOffCostsAtLeastFourAndTheBallComesInHandInTheD) {
  const Shot shot = makeShot(snookerLayout(3), Intent::none(),
                             LogBuilder().hit(0, 1).pocket(0, "foot_left_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed)) << describe(v);
  EXPECT_EQ(v.penalty, 4);
  EXPECT_EQ(v.next.ball_in_hand, BallInHand::InTheD);
  EXPECT_FALSE(snookerOffers(v, Choice::FreeBall));  // in hand: never snookered
}

TEST(SnookerFoul, AFoulAfterARedBeforeAColourIsNominatedCostsSeven) {
  const Shot shot = makeShot(snookerLayout(3), Intent::none(), LogBuilder().cushion(0, "head"));
  const Verdict v = snookerJudged(snookerInPlay(0, kOnColour), shot);
  EXPECT_TRUE(v.hasFoul(Foul::NoBallHit)) << describe(v);
  EXPECT_EQ(v.penalty, 7);
}

TEST(SnookerFoul, ABallOffTheTableIsAFoulAndAColourComesBack) {
  const Shot shot = makeShot(snookerLayout(3), Intent::none(),
                             LogBuilder().hit(0, 1).hit(1, kSnookerGreen).offTable(kSnookerGreen));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::ObjectBallOffTable)) << describe(v);
  EXPECT_EQ(v.penalty, 4);  // the green is worth 3: the least penalty is 4
  EXPECT_EQ(respotPos(v, kSnookerGreen), colourSpot(kSnookerGreen));
}

TEST(SnookerFoul, PassBackHasTheOffenderPlayAgain) {
  const Shot shot = makeShot(
      snookerLayout(3), Intent::none(),
      LogBuilder().hit(0, 1).hit(1, kSnookerPink).pocket(kSnookerPink, "foot_right_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  auto back = applySnookerChoice(v.next, Choice::PassBack);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->next.shooter, 0);
  EXPECT_TRUE(back->next.options.empty());
  EXPECT_FALSE(applySnookerChoice(v.next, Choice::Replace));  // no miss: not offered
}

// ---- Section 3, "Spotting Colours": own spot; else the highest free spot; else as near its own
// spot as possible toward the top cushion.

TEST(SnookerRespot, AnOccupiedSpotSendsTheColourToTheHighestFreeSpot) {
  auto balls = snookerLayout(3);
  // A red sits on the black's spot and the pink has been played off its own; the black is
  // potted on a foul. The highest free spot is the pink's.
  balls[1].pos = physics::Vec3(colourSpot(kSnookerBlack).x(), 0.0, kSnookerR);
  for (auto& b : balls) {
    if (b.id == kSnookerPink) b.pos = physics::Vec3(0.0, -0.6, kSnookerR);
  }
  const Shot shot = makeShot(
      balls, Intent::none(),
      LogBuilder().hit(0, 2).hit(2, kSnookerBlack).pocket(kSnookerBlack, "foot_left_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_EQ(respotPos(v, kSnookerBlack), colourSpot(kSnookerPink)) << describe(v);
}

TEST(SnookerRespot, EverySpotTakenSendsItTowardTheTopCushion) {
  // Reds on every spot; the pink potted (a foul) goes up the long string from its spot, to the
  // first point where it touches nothing: just clear of the red on its spot (0.5 mm steps).
  std::vector<physics::Ball> balls{snookerBall(0, -0.6, -0.4)};
  for (int c = kSnookerYellow; c <= kSnookerBlack; ++c) {
    const Eigen::Vector2d s = colourSpot(c);
    balls.push_back(snookerBall(c - kSnookerYellow + 1, s.x(), s.y()));
  }
  const Eigen::Vector2d pink = colourSpot(kSnookerPink);
  balls.push_back(snookerBall(kSnookerPink, 0.0, 0.6));
  const Shot shot =
      makeShot(balls, Intent::none(),
               LogBuilder().hit(0, 2).hit(2, kSnookerPink).pocket(kSnookerPink, "left_side"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  const Eigen::Vector2d at = respotPos(v, kSnookerPink);
  EXPECT_EQ(at.y(), pink.y());
  EXPECT_GE(at.x() - pink.x(), 2.0 * kSnookerR);
  EXPECT_LT(at.x() - pink.x(), 2.0 * kSnookerR + 5e-4);
}

// ---- Section 3, "Snookered after a Foul": a free ball.

TEST(SnookerFreeBall, AFoulThatLeavesTheCueBallSnookeredOffersAFreeBall) {
  // One red left at the top; the cue ball behind the green, its path to the red blocked.
  std::vector<physics::Ball> balls{
      snookerBall(0, colourSpot(kSnookerGreen).x() - 0.1, colourSpot(kSnookerGreen).y()),
      snookerBall(1, 1.5, colourSpot(kSnookerGreen).y())};
  for (int c = kSnookerYellow; c <= kSnookerBlack; ++c) balls.push_back(onItsSpot(c));
  const std::vector<int> reds{1};
  EXPECT_TRUE(isSnookered(balls, reds, kSnookerR));
  EXPECT_FALSE(isSnookered(snookerLayout(1, -0.6, 0.6), reds, kSnookerR));  // the red in plain view
  // The offender misses everything and leaves the cue ball where it was.
  const Shot shot = makeShot(balls, Intent::none(), LogBuilder().cushion(0, "head"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(snookerOffers(v, Choice::FreeBall)) << describe(v);
  // The free ball: the green nominated, potted, scores as a red (1) and goes back on its spot.
  auto free = applySnookerChoice(v.next, Choice::FreeBall);
  ASSERT_TRUE(free) << free.error();
  EXPECT_TRUE(free->next.free_ball);
  const Shot play =
      makeShot(balls, nominated(kSnookerGreen),
               LogBuilder().hit(0, kSnookerGreen).pocket(kSnookerGreen, "head_left_corner"));
  const Verdict f = snookerJudged(free->next, play);
  EXPECT_TRUE(f.legal()) << describe(f);
  EXPECT_EQ(f.scored, 1);
  EXPECT_EQ(respotPos(f, kSnookerGreen), colourSpot(kSnookerGreen));
  EXPECT_EQ(f.next.ball_on, kOnColour);
  // Without the free ball, hitting the green first is a foul.
  GameState plain = free->next;
  plain.free_ball = false;
  const Verdict foul =
      snookerJudged(plain, makeShot(balls, Intent::none(), LogBuilder().hit(0, kSnookerGreen)));
  EXPECT_TRUE(foul.hasFoul(Foul::WrongBallFirst)) << describe(foul);
}

// ---- Section 3, "Foul and a Miss".

TEST(SnookerMiss, MissingTheBallOnIsAMissAndTheTableCanBePutBack) {
  auto balls = snookerLayout(3);
  const Shot shot = makeShot(balls, Intent::none(),
                             LogBuilder()
                                 .cushion(0, "head")
                                 .hit(0, kSnookerBrown)
                                 .pocket(kSnookerBrown, "head_left_corner"));
  const Verdict v = snookerJudged(snookerInPlay(0), shot);
  EXPECT_TRUE(v.miss) << describe(v);
  EXPECT_TRUE(snookerOffers(v, Choice::Replace));
  EXPECT_EQ(v.next.misses[0], 1);  // the reds were in plain view
  auto replaced = applySnookerChoice(v.next, Choice::Replace);
  ASSERT_TRUE(replaced) << replaced.error();
  EXPECT_EQ(replaced->next.shooter, 0);  // the offender plays again
  EXPECT_EQ(replaced->next.ball_on, kOnRed);
  EXPECT_EQ(replaced->next.points, (std::array<int, 2>{0, 4}));  // the penalty stands
  EXPECT_EQ(replaced->respots.size(), balls.size());             // every ball back where it stood
  for (const auto& b : balls) EXPECT_EQ(respotPos(*replaced, b.id), b.pos.head<2>()) << b.id;
}

TEST(SnookerMiss, ThreeMissesWithTheBallOnInPlainViewLoseTheFrame) {
  GameState s = snookerInPlay(0);
  const Shot shot = makeShot(snookerLayout(3), Intent::none(), LogBuilder().cushion(0, "head"));
  for (int attempt = 1; attempt <= 3; ++attempt) {
    const Verdict v = snookerJudged(s, shot);
    ASSERT_TRUE(v.miss) << describe(v);
    if (attempt < 3) {
      EXPECT_FALSE(v.game_over);
      auto replaced = applySnookerChoice(v.next, Choice::Replace);
      ASSERT_TRUE(replaced);
      s = replaced->next;
    } else {
      EXPECT_TRUE(v.game_over);
      EXPECT_EQ(v.end, GameEnd::ThreeMisses);
      EXPECT_EQ(v.winner, 1);
    }
  }
}

TEST(SnookerMiss, NoMissWhenSnookersAreNeeded) {
  // One red and the colours: 35 on the table; 40 behind, the striker needs snookers.
  GameState s = snookerInPlay(0);
  s.points = {0, 40};
  EXPECT_EQ(pointsRemaining(s, snookerLayout(1)), 35);
  EXPECT_EQ(snookersRequired(s, snookerLayout(1), 0), 5);
  const Verdict v =
      snookerJudged(s, makeShot(snookerLayout(1), Intent::none(), LogBuilder().cushion(0, "head")));
  EXPECT_FALSE(v.legal());
  EXPECT_FALSE(v.miss) << describe(v);
  EXPECT_FALSE(snookerOffers(v, Choice::Replace));
}

TEST(SnookerPoints, TheTableHoldsOneHundredAndFortySeven) {
  // 15 reds each with the black, then 27 for the colours (2+3+4+5+6+7).
  std::vector<physics::Ball> balls;
  for (const auto& p : table::snookerRack(snookerTable().spec, kSnookerR))
    balls.push_back(physics::restingBall(p.id, p.pos, kSnookerR));
  EXPECT_EQ(pointsRemaining(newFrame(0), balls), 147);
  GameState on_colour = snookerInPlay(0, kOnColour);
  EXPECT_EQ(pointsRemaining(on_colour, snookerLayout(0)), 34);  // the last red's colour, then 27
}

// ---- Section 3, "Touching Ball".

TEST(SnookerTouching, PlayingAwayFromATouchingRedIsNoFoul) {
  auto balls = snookerLayout(3);
  balls[0].pos.x() = balls[1].pos.x() - 2.0 * kSnookerR;  // the cue ball touching red 1
  balls[0].pos.y() = balls[1].pos.y();
  const Verdict v = snookerJudged(snookerInPlay(0),
                                  makeShot(balls, Intent::none(), LogBuilder().cushion(0, "head")));
  EXPECT_TRUE(v.legal()) << describe(v);
  // Moving it with the stroke is a push.
  physics::Event push;
  push.t = 0.001;
  push.type = physics::EventType::BallBall;
  push.ball_a = 0;
  push.ball_b = 1;
  push.pos = balls[1].pos;
  const Verdict p =
      snookerJudged(snookerInPlay(0), makeShot(balls, Intent::none(), LogBuilder().raw(push)));
  EXPECT_TRUE(p.hasFoul(Foul::PushStroke)) << describe(p);
}

// ---- Section 3, "Play": the end of the frame.

TEST(SnookerEnd, TheLastBlackEndsTheFrame) {
  std::vector<physics::Ball> balls{snookerBall(0, 1.0, 0.2), onItsSpot(kSnookerBlack)};
  GameState s = snookerInPlay(1, kSnookerBlack);
  s.points = {50, 48};
  const Verdict v = snookerJudged(
      s, makeShot(balls, Intent::none(),
                  LogBuilder().hit(0, kSnookerBlack).pocket(kSnookerBlack, "foot_left_corner")));
  EXPECT_TRUE(v.game_over) << describe(v);
  EXPECT_EQ(v.end, GameEnd::FrameOver);
  EXPECT_EQ(v.winner, 1);  // 55 to 50
  // A foul on the last black ends it too: the penalty decides.
  const Verdict foul =
      snookerJudged(s, makeShot(balls, Intent::none(),
                                LogBuilder().hit(0, kSnookerBlack).pocket(0, "foot_left_corner")));
  EXPECT_TRUE(foul.game_over) << describe(foul);
  EXPECT_EQ(foul.winner, 0);  // 57 to 48
}

TEST(SnookerEnd, ATieRespotsTheBlackAndTheNonBreakerPlaysFromTheD) {
  std::vector<physics::Ball> balls{snookerBall(0, 1.0, 0.2), onItsSpot(kSnookerBlack)};
  GameState s = snookerInPlay(1, kSnookerBlack);
  s.points = {50, 43};
  const Verdict v = snookerJudged(
      s, makeShot(balls, Intent::none(),
                  LogBuilder().hit(0, kSnookerBlack).pocket(kSnookerBlack, "foot_left_corner")));
  EXPECT_FALSE(v.game_over) << describe(v);
  EXPECT_EQ(v.next.points, (std::array<int, 2>{50, 50}));
  EXPECT_EQ(respotPos(v, kSnookerBlack), colourSpot(kSnookerBlack));
  EXPECT_EQ(v.next.shooter, 1);  // seat 0 broke
  EXPECT_EQ(v.next.ball_in_hand, BallInHand::InTheD);
  EXPECT_EQ(v.next.ball_on, kSnookerBlack);
}

// ---- Section 3, "Stalemate": the frame is started again by the same player.

TEST(SnookerStalemate, StrokesWithoutAPotRestartTheFrame) {
  GameState s = snookerInPlay(1);
  s.dry_turns = 5;
  s.points = {20, 12};
  const auto v =
      judgeSnooker(s, makeShot(snookerLayout(3), Intent::none(), LogBuilder().hit(0, 1).cushion(1)),
                   snookerTable(), SnookerConfig{6});
  ASSERT_TRUE(v) << v.error();
  EXPECT_TRUE(v->rerack && v->stalemate) << describe(*v);
  EXPECT_EQ(v->next.points, (std::array<int, 2>{0, 0}));
  EXPECT_EQ(v->next.shooter, 0);
  EXPECT_EQ(v->next.ball_in_hand, BallInHand::InTheD);
}

// ---- What the referee refuses to hear.

TEST(SnookerIntent, OnlyAColourIsNominatedAndOnlyWhenOnOne) {
  EXPECT_FALSE(checkSnookerIntent(snookerInPlay(0), nominated(kSnookerBlack)));
  EXPECT_TRUE(checkSnookerIntent(snookerInPlay(0, kOnColour), nominated(kSnookerBlack)));
  EXPECT_FALSE(checkSnookerIntent(snookerInPlay(0, kOnColour), nominated(3)));
  EXPECT_FALSE(checkSnookerIntent(snookerInPlay(0), Intent::call(1, "left_side")));
  EXPECT_FALSE(checkSnookerIntent(snookerInPlay(0), Intent::safe()));
  GameState free = snookerInPlay(0);
  free.free_ball = true;
  EXPECT_TRUE(checkSnookerIntent(free, nominated(kSnookerBlue)));
}

TEST(SnookerGame, TheGameKitKnowsSnooker) {
  const auto game = gameOfName("snooker");
  ASSERT_TRUE(game);
  EXPECT_EQ(tableOf(*game, "pool-9ft"), "snooker-12ft");
  EXPECT_EQ(rackTypeOf(*game), table::RackType::Snooker);
  const GameState s = newRackOf(*game, 1);
  EXPECT_EQ(s.ball_in_hand, BallInHand::InTheD);
  EXPECT_EQ(s.ball_on, kOnRed);
  EXPECT_EQ(s.shooter, 1);
  GameRules rules;
  rules.game = *game;
  EXPECT_EQ(firstBallsFor(rules, snookerInPlay(0), snookerLayout(2)), (std::vector<int>{1, 2}));
  EXPECT_EQ(firstBallsFor(rules, snookerInPlay(0, kSnookerPink), snookerLayout(2)),
            (std::vector<int>{kSnookerPink}));
}

// ---- Found on reading the rules again.

TEST(SnookerClock, TheClockRunOutWithTheCueBallInHandLeavesItInHand) {
  // The cue ball potted on the last stroke: the shooter has it in hand in the D and lets the
  // clock run out. A foul (4 away); the opponent, too, has the cue ball in hand in the D.
  auto balls = snookerLayout(3);
  balls[0].state = physics::MotionState::Pocketed;
  GameState s = snookerInPlay(1);
  s.ball_in_hand = BallInHand::InTheD;
  Shot shot;
  shot.before = balls;
  shot.after = balls;
  shot.clock_expired = true;
  const Verdict v = snookerJudged(s, shot);
  EXPECT_TRUE(v.hasFoul(Foul::ShotClockExpired)) << describe(v);
  EXPECT_EQ(v.penalty, 4);
  EXPECT_EQ(v.next.ball_in_hand, BallInHand::InTheD);
}

TEST(SnookerEnd, ATieByAFoulOnTheLastBlackRespotsItAndOffersNoChoice) {
  // Only the black, away from its spot; the breaker (seat 0) leads 67-60 and goes in-off it: 7
  // away, 67-67. The black goes back on its spot and the non-breaker plays from the D.
  std::vector<physics::Ball> balls{snookerBall(0, 0.8, 0.3), snookerBall(kSnookerBlack, 1.2, 0.4)};
  GameState s = snookerInPlay(0, kSnookerBlack);
  s.points = {67, 60};
  const Verdict v =
      snookerJudged(s, makeShot(balls, Intent::none(),
                                LogBuilder().hit(0, kSnookerBlack).pocket(0, "foot_left_corner")));
  EXPECT_FALSE(v.game_over) << describe(v);
  EXPECT_EQ(v.next.points, (std::array<int, 2>{67, 67}));
  EXPECT_EQ(respotPos(v, kSnookerBlack), colourSpot(kSnookerBlack));
  EXPECT_TRUE(v.options.empty());
  EXPECT_TRUE(v.next.options.empty());
  EXPECT_EQ(v.next.shooter, 1);
  EXPECT_EQ(v.next.ball_in_hand, BallInHand::InTheD);
  EXPECT_EQ(v.next.ball_on, kSnookerBlack);
}

TEST(SnookerRespot, ColoursWhoseOwnSpotsAreFreeGoThereFirst) {
  // A red on the black's spot, the blue played off its own; the pink and the black potted on a
  // foul. The pink takes its own spot; the black the highest spot left, the blue's.
  auto balls = snookerLayout(3);
  balls[1].pos = physics::Vec3(colourSpot(kSnookerBlack).x(), 0.0, kSnookerR);
  for (auto& b : balls) {
    if (b.id == kSnookerBlue) b.pos = physics::Vec3(-0.3, -0.6, kSnookerR);
  }
  const Verdict v =
      snookerJudged(snookerInPlay(0), makeShot(balls, Intent::none(),
                                               LogBuilder()
                                                   .hit(0, 2)
                                                   .hit(2, kSnookerPink)
                                                   .hit(kSnookerPink, kSnookerBlack)
                                                   .pocket(kSnookerPink, "foot_left_corner")
                                                   .pocket(kSnookerBlack, "foot_right_corner")));
  EXPECT_EQ(respotPos(v, kSnookerPink), colourSpot(kSnookerPink)) << describe(v);
  EXPECT_EQ(respotPos(v, kSnookerBlack), colourSpot(kSnookerBlue)) << describe(v);
}

TEST(SnookerMiss, ReplacingAMissedFreeBallGivesTheFreeBallBack) {
  GameState s = snookerInPlay(0);
  s.free_ball = true;
  const Verdict v =
      snookerJudged(s, makeShot(snookerLayout(3), Intent::none(), LogBuilder().cushion(0, "head")));
  ASSERT_TRUE(v.miss) << describe(v);
  auto replaced = applySnookerChoice(v.next, Choice::Replace);
  ASSERT_TRUE(replaced) << replaced.error();
  EXPECT_TRUE(replaced->next.free_ball);
  EXPECT_EQ(replaced->next.shooter, 0);
}

TEST(SnookerMiss, SnookersNeededAfterAFoulOnTheLastRedsColourAreCountedFromTheYellow) {
  // After the last red, on a colour, 25 behind: the stroke hits nothing (7 away, 32 behind).
  // Before it 34 were on the table (the colour due, then 27); after it the yellow is on and 27
  // are left: snookers are needed, so no miss is called.
  GameState s = snookerInPlay(0, kOnColour);
  s.points = {0, 25};
  const Verdict v =
      snookerJudged(s, makeShot(snookerLayout(0), Intent::none(), LogBuilder().cushion(0, "head")));
  EXPECT_EQ(v.penalty, 7);
  EXPECT_EQ(v.next.ball_on, kSnookerYellow);
  EXPECT_EQ(snookersRequired(v.next, snookerLayout(0), 0), 5);
  EXPECT_FALSE(v.miss) << describe(v);
}

// ---- Section 2, "Definitions" ("Jump Shot"), and Section 3, "Fouls": the jump shot.

/// An event of the cue ball at (x, y) on the cloth's plane (its centre's height is not judged).
physics::Event cueEvent(physics::EventType type, double t, double x, double y) {
  physics::Event e;
  e.t = t;
  e.type = type;
  e.ball_a = physics::kCueBall;
  e.pos = physics::Vec3(x, y, kSnookerR);
  return e;
}

/// The cue ball at (0, 0.3), a red 0.15 m ahead of it and another 0.5 m ahead.
std::vector<physics::Ball> jumpLayout() {
  return {snookerBall(0, 0.0, 0.3), snookerBall(1, 0.15, 0.3), snookerBall(2, 0.5, 0.3),
          onItsSpot(kSnookerBlack)};
}

TEST(SnookerJump, JumpingOverABallBeforeTheFirstContactIsAFoul) {
  using physics::EventType;
  // Off the slate at the strike, down again 0.3 m on, beyond the near red, then on to the far one.
  const Shot over = makeShot(jumpLayout(), Intent::none(),
                             LogBuilder()
                                 .raw(cueEvent(EventType::Airborne, 0.01, 0.0, 0.3))
                                 .raw(cueEvent(EventType::Land, 0.1, 0.3, 0.3))
                                 .hit(0, 2));
  const Verdict v = snookerJudged(snookerInPlay(0), over);
  EXPECT_TRUE(v.hasFoul(Foul::JumpShot)) << describe(v);
  EXPECT_EQ(v.penalty, 4);  // the value of the ball on (a red), at least 4
  EXPECT_FALSE(v.miss);     // the red it first hit was on
  // The same hop landing short of the near red, which it then hits on the cloth: no jump shot.
  const Shot hop = makeShot(jumpLayout(), Intent::none(),
                            LogBuilder()
                                .raw(cueEvent(EventType::Airborne, 0.01, 0.0, 0.3))
                                .raw(cueEvent(EventType::Land, 0.05, 0.08, 0.3))
                                .hit(0, 1));
  EXPECT_TRUE(snookerJudged(snookerInPlay(0), hop).legal());
}

TEST(SnookerJump, TheRulesExceptionsAreNoFoul) {
  using physics::EventType;
  // (i) The cue ball first strikes a ball on the cloth, then jumps over another.
  const Shot after_contact = makeShot(jumpLayout(), Intent::none(),
                                      LogBuilder()
                                          .hit(0, 1)
                                          .raw(cueEvent(EventType::Airborne, 0.2, 0.12, 0.3))
                                          .raw(cueEvent(EventType::Land, 0.4, 0.7, 0.3)));
  EXPECT_TRUE(snookerJudged(snookerInPlay(0), after_contact).legal());
  // (ii) It jumps, strikes a ball in the air and does not land on the far side of it ...
  const Shot near_side = makeShot(jumpLayout(), Intent::none(),
                                  LogBuilder()
                                      .raw(cueEvent(EventType::Airborne, 0.01, 0.0, 0.3))
                                      .hit(0, 1)
                                      .raw(cueEvent(EventType::Land, 0.1, 0.09, 0.3)));
  EXPECT_TRUE(snookerJudged(snookerInPlay(0), near_side).legal());
  // ... but landing beyond the ball it struck in the air is a jump shot.
  const Shot far_side = makeShot(jumpLayout(), Intent::none(),
                                 LogBuilder()
                                     .raw(cueEvent(EventType::Airborne, 0.01, 0.0, 0.3))
                                     .hit(0, 1)
                                     .raw(cueEvent(EventType::Land, 0.1, 0.25, 0.3)));
  EXPECT_TRUE(snookerJudged(snookerInPlay(0), far_side).hasFoul(Foul::JumpShot));
  // A thin hit in the air: the cue ball meets the red's edge beside it and flies on past it, its
  // centre never over the red's: no jump shot.
  physics::Event thin;
  thin.t = 0.05;
  thin.type = EventType::BallBall;
  thin.ball_a = physics::kCueBall;
  thin.ball_b = 1;
  thin.pos = physics::Vec3(0.15 - 0.01, 0.3 - 2 * kSnookerR + 0.001, kSnookerR);
  const Shot thin_hit = makeShot(jumpLayout(), Intent::none(),
                                 LogBuilder()
                                     .raw(cueEvent(EventType::Airborne, 0.01, 0.0, 0.3 - 0.05))
                                     .raw(thin)
                                     .raw(cueEvent(EventType::Land, 0.1, 0.3, 0.3 - 0.07)));
  EXPECT_FALSE(snookerJudged(snookerInPlay(0), thin_hit).hasFoul(Foul::JumpShot));
}

TEST(SnookerJump, TheRealPhysicsJumpOverARedIsCalled) {
  // The physics' own jump (an elevated cue drives the ball into the slate; tests/physics'
  // Jump.ElevatedCueBouncesOffTheSlateAndClearsABlocker) on the snooker table, over a red 0.15 m
  // ahead toward another 0.6 m ahead; a level cue hits the near red: no jump shot.
  const auto scene = [](double elevation) {
    return test::parsed(R"({
      "table": "snooker-12ft",
      "balls": [ {"id": 0, "x": -0.8, "y": 0.5}, {"id": 1, "x": -0.65, "y": 0.5},
                 {"id": 2, "x": -0.2, "y": 0.5}, {"id": 21, "x": 1.4, "y": 0.0} ],
      "shot": {"yaw_deg": 0.0, "tip_side": 0.0, "tip_height": 0.0, "elevation_deg": )" +
                        std::to_string(elevation) + R"(, "speed": 4.0, "speed_is": "cue"}
    })");
  };
  const test::Played jump = test::play(scene(45.0), Intent::none());
  const auto lands = std::find_if(jump.shot.events.begin(), jump.shot.events.end(), [](auto& e) {
    return e.type == physics::EventType::Land && e.ball_a == physics::kCueBall;
  });
  ASSERT_NE(lands, jump.shot.events.end()) << "the cue ball never left the slate";
  const Verdict v = snookerJudged(snookerInPlay(0), jump.shot);
  if (lands->pos.x() > -0.65) {
    EXPECT_TRUE(v.hasFoul(Foul::JumpShot)) << describe(v);
  } else {
    ADD_FAILURE() << "the jump landed short of the red, at x " << lands->pos.x();
  }
  const test::Played level = test::play(scene(0.0), Intent::none());
  const Verdict l = snookerJudged(snookerInPlay(0), level.shot);
  EXPECT_FALSE(l.hasFoul(Foul::JumpShot)) << describe(l);
}

// ---- Section 3, "Snookered after a Foul" (the free ball may not snooker the next player).

TEST(SnookerFreeBall, AFreeBallThatSnookersTheNextPlayerIsAFoul) {
  // One red at the top; the green nominated as the free ball. The stroke hits the green first
  // and the cue ball comes to rest straight behind it, the red hidden by the green alone.
  const Vec2 green = colourSpot(kSnookerGreen);
  std::vector<physics::Ball> balls{snookerBall(0, green.x() - 0.3, green.y() - 0.2),
                                   snookerBall(1, 1.5, green.y())};
  for (int c = kSnookerYellow; c <= kSnookerBlack; ++c) balls.push_back(onItsSpot(c));
  GameState s = snookerInPlay(0);
  s.free_ball = true;
  const auto stroke = [&](const Vec2& cue_rests) {
    Shot shot = makeShot(balls, nominated(kSnookerGreen), LogBuilder().hit(0, kSnookerGreen));
    shot.after[0].pos.head<2>() = cue_rests;
    return shot;
  };
  const Verdict snookered = snookerJudged(s, stroke(Vec2(green.x() - 0.1, green.y())));
  EXPECT_TRUE(snookered.hasFoul(Foul::FreeBallSnookers)) << describe(snookered);
  EXPECT_EQ(snookered.penalty, 4);
  EXPECT_FALSE(snookered.miss);
  EXPECT_EQ(snookered.next.points, (std::array<int, 2>{0, 4}));
  // Resting where the red is in plain view: a legal stroke.
  const Verdict open = snookerJudged(s, stroke(Vec2(green.x() - 0.1, green.y() - 0.2)));
  EXPECT_TRUE(open.legal()) << describe(open);
}

TEST(SnookerFreeBall, WithOnlyThePinkAndBlackLeftTheFreeBallMaySnooker) {
  // On the pink, the black nominated as the free ball; the cue ball rests behind the black, the
  // pink hidden by it: no foul with only the pink and black left.
  const Vec2 pink = colourSpot(kSnookerPink), black = colourSpot(kSnookerBlack);
  std::vector<physics::Ball> balls{snookerBall(0, black.x() - 0.3, black.y() + 0.3),
                                   onItsSpot(kSnookerPink), onItsSpot(kSnookerBlack)};
  GameState s = snookerInPlay(0, kSnookerPink);
  s.free_ball = true;
  Shot shot = makeShot(balls, nominated(kSnookerBlack), LogBuilder().hit(0, kSnookerBlack));
  shot.after[0].pos.head<2>() = black + (black - pink).normalized() * 0.1;
  ASSERT_TRUE(isSnookered(shot.after, {kSnookerPink}, kSnookerR));
  const Verdict v = snookerJudged(s, shot);
  EXPECT_FALSE(v.hasFoul(Foul::FreeBallSnookers)) << describe(v);
}

}  // namespace
}  // namespace pool::rules
