// Three-cushion on built logs, clause by clause after the UMB's World Rules of Carom Billiard
// (articles as numbered in the 1989 edition: 23 starting position, 28 balls bounding out of the
// billiard, 41 fouls, 83 three cushions) and its sports rules for three-cushion events (innings
// and runs, the match to a number of points).
#include <gtest/gtest.h>

#include "rules/fixture.h"
#include "rules/game_rules.h"
#include "rules/three_cushion.h"
#include "table/rack.h"

namespace pool::rules {
namespace {

using test::LogBuilder;
using test::makeShot;

constexpr double kR = 0.03075;  // a carom ball's radius (61.5 mm across)

TableContext caromTable() {
  auto spec = table::loadTableSpec("carom-match");
  EXPECT_TRUE(spec) << spec.error();
  return tableContext(*spec);
}

physics::Ball caromBall(int id, double x, double y) {
  return physics::restingBall(id, Eigen::Vector2d(x, y), kR);
}

// The balls apart in mid-table: white, yellow, red.
std::vector<physics::Ball> caromSpread() {
  return {caromBall(kCaromWhite, -0.5, 0.2), caromBall(kCaromYellow, 0.3, -0.3),
          caromBall(kCaromRed, 0.6, 0.4)};
}

// Play after the opening: seat 0 broke (the white is its ball), `shooter` at the table.
GameState caromInPlay(int shooter) {
  GameState s = newRack(0);
  s.phase = Phase::Open;
  s.ball_in_hand = BallInHand::None;
  s.shooter = shooter;
  return s;
}

const ThreeCushionConfig kToFive{5};

Verdict caromJudged(const GameState& state, const Shot& shot,
                    const ThreeCushionConfig& c = kToFive) {
  auto v = judgeThreeCushion(state, shot, caromTable(), c);
  EXPECT_TRUE(v) << v.error();
  return v ? *v : Verdict{};
}

// ---- Art. 83: a point when the cue ball touches both object balls and, before it touches the
// second, at least three cushions.

TEST(ThreeCushionPoint, ThreeCushionsBeforeTheSecondBallScore) {
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .hit(kCaromWhite, kCaromRed)
                                 .cushion(kCaromWhite, "left")
                                 .cushion(kCaromWhite, "foot")
                                 .cushion(kCaromWhite, "right")
                                 .hit(kCaromWhite, kCaromYellow));
  const Verdict v = caromJudged(caromInPlay(0), shot);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.scored, 1);
  EXPECT_TRUE(v.turn_continues);  // the striker plays on while he scores
  EXPECT_EQ(v.next.shooter, 0);
  EXPECT_EQ(v.next.points, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(v.next.run, 1);
  EXPECT_EQ(v.next.innings, (std::array<int, 2>{0, 0}));  // the inning goes on
}

TEST(ThreeCushionPoint, TheThirdCushionMayComeAfterTheFirstObjectBall) {
  // Two cushions first (a "bank" shot), then the red, a third cushion, then the yellow.
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .cushion(kCaromWhite, "head")
                                 .cushion(kCaromWhite, "left")
                                 .hit(kCaromWhite, kCaromRed)
                                 .cushion(kCaromWhite, "foot")
                                 .hit(kCaromWhite, kCaromYellow));
  const Verdict v = caromJudged(caromInPlay(0), shot);
  EXPECT_EQ(v.scored, 1) << describe(v);
}

TEST(ThreeCushionPoint, TheSameCushionTwiceCountsTwice) {
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .hit(kCaromWhite, kCaromYellow)
                                 .cushion(kCaromWhite, "left")
                                 .cushion(kCaromWhite, "right")
                                 .cushion(kCaromWhite, "left")
                                 .hit(kCaromWhite, kCaromRed));
  EXPECT_EQ(caromJudged(caromInPlay(0), shot).scored, 1);
}

TEST(ThreeCushionPoint, TwoCushionsBeforeTheSecondBallAreNoPoint) {
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .hit(kCaromWhite, kCaromRed)
                                 .cushion(kCaromWhite, "left")
                                 .cushion(kCaromWhite, "foot")
                                 .hit(kCaromWhite, kCaromYellow)
                                 .cushion(kCaromWhite, "right"));  // after the second: no count
  GameState state = caromInPlay(0);
  state.run = 3;
  state.high_run = {2, 0};
  const Verdict v = caromJudged(state, shot);
  EXPECT_TRUE(v.legal());  // a miss is no foul: it only ends the inning
  EXPECT_EQ(v.scored, 0);
  EXPECT_FALSE(v.turn_continues);
  EXPECT_EQ(v.next.shooter, 1);
  EXPECT_EQ(v.next.innings, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(v.next.run, 0);
  EXPECT_EQ(v.next.high_run, (std::array<int, 2>{2, 0}));
}

TEST(ThreeCushionPoint, OneObjectBallIsNoPointWhateverTheCushions) {
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .cushion(kCaromWhite, "left")
                                 .cushion(kCaromWhite, "foot")
                                 .cushion(kCaromWhite, "right")
                                 .cushion(kCaromWhite, "head")
                                 .hit(kCaromWhite, kCaromRed));
  EXPECT_EQ(caromJudged(caromInPlay(0), shot).scored, 0);
}

TEST(ThreeCushionPoint, ContactsBetweenTheObjectBallsDoNotCount) {
  // The red knocked into the yellow is not the cue ball touching the yellow.
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .hit(kCaromWhite, kCaromRed)
                                 .cushion(kCaromWhite, "left")
                                 .cushion(kCaromWhite, "foot")
                                 .cushion(kCaromWhite, "right")
                                 .hit(kCaromRed, kCaromYellow));
  EXPECT_EQ(caromJudged(caromInPlay(0), shot).scored, 0);
}

TEST(ThreeCushionPoint, TheOtherPlayerStrikesTheYellow) {
  // Seat 1 did not break: its ball is the yellow, and the white is one of its object balls.
  const Shot yellow = makeShot(caromSpread(), Intent::none(),
                               LogBuilder::striking(kCaromYellow)
                                   .hit(kCaromYellow, kCaromWhite)
                                   .cushion(kCaromYellow, "left")
                                   .cushion(kCaromYellow, "foot")
                                   .cushion(kCaromYellow, "right")
                                   .hit(kCaromYellow, kCaromRed));
  const Verdict v = caromJudged(caromInPlay(1), yellow);
  EXPECT_EQ(v.scored, 1);
  EXPECT_EQ(v.next.points, (std::array<int, 2>{0, 1}));
  // Striking the white out of turn is refused: the log must start with the shooter's ball.
  const Shot white = makeShot(caromSpread(), Intent::none(),
                              LogBuilder::striking(kCaromWhite).hit(kCaromWhite, kCaromRed));
  EXPECT_FALSE(judgeThreeCushion(caromInPlay(1), white, caromTable(), kToFive));
  EXPECT_EQ(caromBallOf(caromInPlay(1), 1), kCaromYellow);
  EXPECT_EQ(caromBallOf(caromInPlay(1), 0), kCaromWhite);
}

// ---- Art. 23: the opening, the red first; innings and runs.

TEST(ThreeCushionOpening, TheBreakersBallOnTheHeadStringBesideTheOpponentsOnTheSpot) {
  auto spec = table::loadTableSpec("carom-match");
  ASSERT_TRUE(spec);
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const auto opening = table::caromOpening(*spec, seed);
    ASSERT_EQ(opening.size(), 3u);
    const double head_x = -2.84 / 4.0, top_x = 2.84 / 4.0;
    EXPECT_NEAR(opening[0].pos.x(), head_x, 1e-12);  // the breaker's white on the head string
    EXPECT_NEAR(std::abs(opening[0].pos.y()), 0.182, 1e-12);  // 182 mm to one side
    EXPECT_NEAR((opening[1].pos - Eigen::Vector2d(head_x, 0)).norm(), 0.0, 1e-12);  // yellow
    EXPECT_NEAR((opening[2].pos - Eigen::Vector2d(top_x, 0)).norm(), 0.0, 1e-12);   // red
  }
}

TEST(ThreeCushionOpening, TheOpeningShotMustHitTheRedFirst) {
  const auto balls = caromSpread();
  const Shot yellow_first = makeShot(balls, Intent::none(),
                                     LogBuilder::striking(kCaromWhite)
                                         .hit(kCaromWhite, kCaromYellow)
                                         .cushion(kCaromWhite, "left")
                                         .cushion(kCaromWhite, "foot")
                                         .cushion(kCaromWhite, "right")
                                         .hit(kCaromWhite, kCaromRed));
  const Verdict v = caromJudged(newRack(0), yellow_first);
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst)) << describe(v);
  EXPECT_EQ(v.scored, 0);
  EXPECT_EQ(v.next.shooter, 1);
  EXPECT_EQ(v.next.phase, Phase::Open);
  // The same carom from the red first scores.
  const Shot red_first = makeShot(balls, Intent::none(),
                                  LogBuilder::striking(kCaromWhite)
                                      .hit(kCaromWhite, kCaromRed)
                                      .cushion(kCaromWhite, "left")
                                      .cushion(kCaromWhite, "foot")
                                      .cushion(kCaromWhite, "right")
                                      .hit(kCaromWhite, kCaromYellow));
  EXPECT_EQ(caromJudged(newRack(0), red_first).scored, 1);
}

TEST(ThreeCushionGame, TheWinningPointEndsTheGameAndItsInning) {
  GameState state = caromInPlay(1);
  state.points = {3, 4};
  state.innings = {6, 5};
  state.run = 2;
  state.high_run = {1, 2};
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromYellow)
                                 .cushion(kCaromYellow, "left")
                                 .cushion(kCaromYellow, "foot")
                                 .cushion(kCaromYellow, "right")
                                 .hit(kCaromYellow, kCaromRed)
                                 .hit(kCaromYellow, kCaromWhite));
  const Verdict v = caromJudged(state, shot);
  EXPECT_TRUE(v.game_over);
  EXPECT_EQ(v.winner, 1);
  EXPECT_EQ(v.end, GameEnd::PointsReached);
  EXPECT_EQ(v.next.phase, Phase::Over);
  EXPECT_EQ(v.next.points, (std::array<int, 2>{3, 5}));
  EXPECT_EQ(v.next.innings, (std::array<int, 2>{6, 6}));
  EXPECT_EQ(v.next.high_run, (std::array<int, 2>{1, 3}));
}

// ---- Art. 28 and 41: a ball leaving the table is a foul; it is set back on its spot.

TEST(ThreeCushionFouls, TheStrikersBallOffTheTableEndsTheInningAndGoesToTheBottomSpot) {
  const Shot shot = makeShot(caromSpread(), Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .hit(kCaromWhite, kCaromRed)
                                 .cushion(kCaromWhite, "left")
                                 .cushion(kCaromWhite, "foot")
                                 .cushion(kCaromWhite, "right")
                                 .hit(kCaromWhite, kCaromYellow)
                                 .airborne(kCaromWhite)
                                 .offTable(kCaromWhite));
  const Verdict v = caromJudged(caromInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallOffTable)) << describe(v);
  EXPECT_EQ(v.scored, 0);  // a foul scores nothing, the carom made or not
  EXPECT_EQ(v.next.shooter, 1);
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, kCaromWhite);
  EXPECT_NEAR((v.respots[0].pos - caromTable().spots.head_spot).norm(), 0.0, 1e-12);
}

TEST(ThreeCushionFouls, ARedOffTheTableGoesToTheTopSpotOrTheSpotOfTheBallOnIt) {
  // The red leaves the table while the yellow rests on the top spot: the red takes the yellow's
  // own spot (the centre spot, the yellow being the opponent's ball).
  const TableContext t = caromTable();
  auto balls = caromSpread();
  balls[1].pos = physics::Vec3(t.spots.foot_spot.x(), t.spots.foot_spot.y(), kR);
  const Shot shot = makeShot(balls, Intent::none(),
                             LogBuilder::striking(kCaromWhite)
                                 .hit(kCaromWhite, kCaromRed)
                                 .airborne(kCaromRed)
                                 .offTable(kCaromRed));
  const Verdict v = caromJudged(caromInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::ObjectBallOffTable)) << describe(v);
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, kCaromRed);
  EXPECT_NEAR((v.respots[0].pos - t.spots.centre_spot).norm(), 0.0, 1e-12);
}

TEST(ThreeCushionFouls, TheShotClockRunOutIsAFoulWithoutAShot) {
  Shot shot;
  shot.before = caromSpread();
  shot.after = shot.before;
  shot.clock_expired = true;
  const Verdict v = caromJudged(caromInPlay(0), shot);
  EXPECT_TRUE(v.hasFoul(Foul::ShotClockExpired));
  EXPECT_EQ(v.next.shooter, 1);
}

TEST(ThreeCushionIntent, NothingIsCalledOrChosen) {
  const Shot called = makeShot(caromSpread(), Intent::call(2, "foot_left_corner"),
                               LogBuilder::striking(kCaromWhite).hit(kCaromWhite, kCaromRed));
  EXPECT_FALSE(judgeThreeCushion(caromInPlay(0), called, caromTable(), kToFive));
  const Shot safety = makeShot(caromSpread(), Intent::safe(),
                               LogBuilder::striking(kCaromWhite).hit(kCaromWhite, kCaromRed));
  EXPECT_FALSE(judgeThreeCushion(caromInPlay(0), safety, caromTable(), kToFive));
  GameRules rules;
  rules.game = Game::ThreeCushion;
  EXPECT_FALSE(applyChoiceFor(rules, caromInPlay(0), Choice::PlayOn, caromSpread(), caromTable()));
  EXPECT_EQ(cueBallFor(rules, caromInPlay(1)), kCaromYellow);
  EXPECT_EQ(firstBallsFor(rules, newRack(0), caromSpread()), (std::vector<int>{kCaromRed}));
  EXPECT_EQ(tableOf(Game::ThreeCushion, "wpa-9ft"), "carom-match");
  EXPECT_EQ(tableOf(Game::NineBall, "wpa-8ft"), "wpa-8ft");
  EXPECT_EQ(gameOfName("three-cushion"), Game::ThreeCushion);
  EXPECT_EQ(gameOfName("9"), Game::NineBall);
  EXPECT_EQ(gameOfName("snooker"), Game::Snooker);
  EXPECT_FALSE(gameOfName("carom"));
}

}  // namespace
}  // namespace pool::rules
