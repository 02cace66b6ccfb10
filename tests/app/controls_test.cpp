// Each control produces the expected ShotCommand fields, inside the server's limits.
#include "client/app/controls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app_fixture.h"
#include "rules/placement.h"
#include "table/snooker_spots.h"

namespace pool::app::test {
namespace {

const ControlRates kRates{};
const protocol::CommandLimits kLimits{};

class ControlsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  }
  Controls controls = nineFootControls();
};

TEST_F(ControlsTest, ArrowsTurnTheCueAtTheirRateRightClockwise) {
  hold(controls, Key::Right, 0.5);
  EXPECT_NEAR(controls.aim().yaw, -heldTurn(0.5), 1e-9);
  hold(controls, Key::Left, 1.5);
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->cue.yaw, heldTurn(1.5) - heldTurn(0.5), 1e-9);
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(ControlsTest, YawWrapsIntoTheWireRange) {
  hold(controls, Key::Left, 20.0);  // 10 rad: past pi more than once
  const double expected = std::remainder(heldTurn(20.0), 2 * std::numbers::pi);
  const auto shot = shoot(controls, 0.1);
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->cue.yaw, expected, 1e-9);
  EXPECT_LE(std::abs(shot->cue.yaw), std::numbers::pi);
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(ControlsTest, CtrlArrowsMoveTheTipOffset) {
  hold(controls, Key::Up, 0.4, {.ctrl = true});
  hold(controls, Key::Left, 0.2, {.ctrl = true});
  const auto shot = shoot(controls, 0.1);
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->cue.tip_height, 0.4 * kRates.tip, 1e-9);
  EXPECT_NEAR(shot->cue.tip_side, -0.2 * kRates.tip, 1e-9);
  EXPECT_DOUBLE_EQ(shot->cue.yaw, 0.0);  // the cue did not turn
}

TEST_F(ControlsTest, TipStaysInsideTheMiscueCircleAlongItsDirection) {
  controls.keyDown(Key::Up, {.ctrl = true});
  controls.keyDown(Key::Right, {.ctrl = true});
  for (int i = 0; i < 600; ++i) controls.advance(1.0 / 60.0);
  controls.keyUp(Key::Up);
  controls.keyUp(Key::Right);
  const auto shot = shoot(controls, 0.1);
  ASSERT_TRUE(shot);
  EXPECT_NEAR(std::hypot(shot->cue.tip_side, shot->cue.tip_height), kLimits.miscue_limit, 1e-6);
  EXPECT_LE(std::hypot(shot->cue.tip_side, shot->cue.tip_height), kLimits.miscue_limit);
  EXPECT_NEAR(shot->cue.tip_side, shot->cue.tip_height, 1e-9);
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(ControlsTest, AAndZSetTheElevationWithinLimits) {
  hold(controls, Key::A, 0.5);
  EXPECT_NEAR(controls.aim().elevation, 0.5 * kRates.elevation, 1e-9);
  hold(controls, Key::Z, 2.0);
  EXPECT_EQ(controls.aim().elevation, 0.0);
  hold(controls, Key::A, 10.0);
  const auto shot = shoot(controls, 0.1);
  ASSERT_TRUE(shot);
  EXPECT_DOUBLE_EQ(shot->cue.elevation, kLimits.max_elevation);
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(ControlsTest, SpaceChargesPowerAndReleaseShoots) {
  const auto soft = shoot(controls, 0.5);
  ASSERT_TRUE(soft);
  EXPECT_NEAR(soft->cue.speed, cueSpeedOf(0.5 / kRates.charge_time, kLimits), 1e-9);
  EXPECT_FALSE(soft->cue.speed_is_ball);
  EXPECT_EQ(controls.mode(), ControlMode::Watching);  // one shot per turn

  controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  const auto full = shoot(controls, 5.0);
  ASSERT_TRUE(full);
  EXPECT_DOUBLE_EQ(full->cue.speed, kLimits.max_speed);
  EXPECT_TRUE(wireCheck(*full).ok());

  controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  const auto tap = shoot(controls, 0.0);
  ASSERT_TRUE(tap);
  EXPECT_DOUBLE_EQ(tap->cue.speed, kMinCueSpeed);
  EXPECT_TRUE(wireCheck(*tap).ok());
}

TEST_F(ControlsTest, EscapeCancelsTheCharge) {
  controls.keyDown(Key::Space, {});
  controls.advance(0.5);
  controls.keyDown(Key::Escape, {});
  controls.keyUp(Key::Space);
  EXPECT_FALSE(controls.takeShot());
  EXPECT_EQ(controls.mode(), ControlMode::Aiming);
}

TEST_F(ControlsTest, ShiftArrowsMoveTheViewNotTheCue) {
  const Orbit before = controls.camera().aimingOrbit();
  hold(controls, Key::Right, 0.5, {.shift = true});
  hold(controls, Key::Up, 0.25, {.shift = true});
  EXPECT_EQ(controls.aim().yaw, 0.0);
  EXPECT_NEAR(controls.camera().aimingOrbit().azimuth - before.azimuth, 0.5 * kRates.orbit, 1e-9);
  EXPECT_NEAR(controls.camera().aimingOrbit().elevation - before.elevation, 0.25 * kRates.raise,
              1e-9);
}

TEST_F(ControlsTest, AimingViewSitsBehindTheCueBall) {
  hold(controls, Key::Left, 1.0);
  const ViewPoint view = controls.camera().view();
  const Eigen::Vector2d back = (view.eye - view.target).head<2>().normalized();
  const double yaw = controls.aim().yaw;
  EXPECT_NEAR(back.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw))), -1.0, 1e-9);
  EXPECT_TRUE(view.target.isApprox(Eigen::Vector3d(-0.8, 0.1, kRadius)));
}

TEST_F(ControlsTest, WatchingArrowsOrbitAndSpaceDoesNothing) {
  controls.stopAiming();
  const Orbit before = controls.camera().watching();
  hold(controls, Key::Left, 0.5);
  hold(controls, Key::Down, 0.25);
  hold(controls, Key::S, 0.5);
  EXPECT_NEAR(controls.camera().watching().azimuth - before.azimuth, -0.5 * kRates.orbit, 1e-9);
  EXPECT_NEAR(controls.camera().watching().elevation - before.elevation, -0.25 * kRates.raise,
              1e-9);
  EXPECT_NEAR(controls.camera().watching().distance / before.distance, std::pow(kRates.zoom, -0.5),
              1e-9);
  EXPECT_FALSE(shoot(controls, 0.5));
  EXPECT_EQ(controls.aim().yaw, 0.0);
}

TEST_F(ControlsTest, DraggingTheMouseTurnsTheCue) {
  controls.mouseButton(MouseButton::Left, true, 600, 400);
  controls.mouseMove(700, 380);
  controls.mouseButton(MouseButton::Left, false, 700, 380);
  EXPECT_NEAR(controls.aim().yaw, -100 * kRates.mouse_yaw, 1e-12);
}

TEST_F(ControlsTest, TheMouseTurnsTheCueAtOneRatePerPixelHoweverTheDragIsCut) {
  // 100 px to the right: in one move, in 1 px moves (the first 2 within the click's slop), or in
  // uneven ones with a move back: always 100 × mouse_yaw.
  const std::vector<std::vector<double>> drags{
      {100.0}, std::vector<double>(100, 1.0), {2.0, 0.5, 37.5, -10.0, 70.0}};
  for (const auto& moves : drags) {
    controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
    controls.setYaw(0.0);
    double x = 600.0;
    controls.mouseButton(MouseButton::Left, true, x, 400);
    for (double dx : moves) controls.mouseMove(x += dx, 400);
    controls.mouseButton(MouseButton::Left, false, x, 400);
    EXPECT_NEAR(controls.aim().yaw, -100 * kRates.mouse_yaw, 1e-12) << moves.size() << " moves";
  }
}

TEST_F(ControlsTest, TheCallCyclesPocketsAndASafetyDropsIt) {
  controls.suggestCall({.ball = 3, .pocket = "foot_left_corner"});
  EXPECT_EQ(controls.aim().call.pocket, "foot_left_corner");
  controls.keyDown(Key::C, {});
  const std::string chosen = controls.aim().call.pocket;
  EXPECT_NE(chosen, "foot_left_corner");
  controls.suggestCall({.ball = 5, .pocket = "side_left"});  // the player's choice stands
  EXPECT_EQ(controls.aim().call.pocket, chosen);
  auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_EQ(shot->called_ball, 3);
  EXPECT_EQ(shot->called_pocket, chosen);
  EXPECT_FALSE(shot->safety);

  controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  controls.suggestCall({.ball = 3, .pocket = "foot_left_corner"});
  controls.keyDown(Key::K, {});
  shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_TRUE(shot->safety);
  EXPECT_FALSE(shot->called_ball);
  EXPECT_TRUE(shot->called_pocket.empty());
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(ControlsTest, ThreeCushionDeclaresNoSafety) {
  // UMB three-cushion has no declared safety (the server's rules refuse one): K does nothing.
  controls.setSafetyDeclared(false);
  controls.keyDown(Key::K, {});
  EXPECT_FALSE(controls.aim().call.safety);
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_FALSE(shot->safety);
  // A pool game's K declares one.
  controls.setSafetyDeclared(true);
  controls.startTurn(Eigen::Vector3d(-0.8, 0.1, kRadius), rules::BallInHand::None);
  controls.keyDown(Key::K, {});
  EXPECT_TRUE(controls.aim().call.safety);
}

TEST_F(ControlsTest, TheOptionGoesWithTheShot) {
  controls.setOption(protocol::ShotOption::PlayOn);
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_EQ(shot->option, protocol::ShotOption::PlayOn);
}

class BallInHandTest : public ::testing::Test {
 protected:
  // The pixel where table point `at` (on the ball-centre plane) appears now.
  Eigen::Vector2d pixelOf(const Eigen::Vector2d& at) const {
    const glm::vec3 p = render::projectToPixels(
        cameraOf(controls.camera().view()), 1280, 720,
        glm::vec3(static_cast<float>(at.x()), static_cast<float>(at.y()), kRadius));
    return {p.x, p.y};
  }
  void drag(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    const Eigen::Vector2d a = pixelOf(from), b = pixelOf(to);
    controls.mouseButton(MouseButton::Left, true, a.x(), a.y());
    EXPECT_TRUE(controls.draggingCueBall());
    for (int i = 1; i <= 10; ++i) {
      const Eigen::Vector2d p = a + (b - a) * (i / 10.0);
      controls.mouseMove(p.x(), p.y());
    }
    controls.mouseButton(MouseButton::Left, false, b.x(), b.y());
  }
  Controls controls = nineFootControls();
};

TEST_F(BallInHandTest, TheBreakPlacementStartsBehindTheHeadString) {
  controls.startTurn(Eigen::Vector3d(-0.635, 0.0, kRadius), rules::BallInHand::BehindHeadString);
  ASSERT_TRUE(controls.aim().cue_ball_at);
  EXPECT_LT(controls.aim().cue_ball_at->x(), PlacementArea{}.head_string_x);
}

TEST_F(BallInHandTest, DraggingTheCueBallPlacesItUnderTheMouse) {
  controls.startTurn(Eigen::Vector3d(0.2, 0.0, kRadius), rules::BallInHand::Anywhere);
  const Eigen::Vector2d target(0.5, 0.3);
  drag(Eigen::Vector2d(0.2, 0.0), target);
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  ASSERT_TRUE(shot->cue_ball_at);
  // A pixel is about a millimetre at this distance.
  EXPECT_LT((*shot->cue_ball_at - target).norm(), 0.003);
  EXPECT_TRUE(wireCheck(*shot).ok());
}

TEST_F(BallInHandTest, TheBallStaysUnderTheCursorAndTheViewStillWhileDragging) {
  controls.startTurn(Eigen::Vector3d(0.2, 0.0, kRadius), rules::BallInHand::Anywhere);
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);  // the turn's glide is over
  const ViewPoint before = controls.camera().view();
  const Eigen::Vector2d a = pixelOf(Eigen::Vector2d(0.2, 0.0));
  controls.mouseButton(MouseButton::Left, true, a.x(), a.y());
  ASSERT_TRUE(controls.draggingCueBall());
  for (int i = 1; i <= 40; ++i) {
    const Eigen::Vector2d cursor = a + Eigen::Vector2d(6.0 * i, -2.5 * i);
    controls.mouseMove(cursor.x(), cursor.y());
    controls.advance(1.0 / 60);  // frames pass while dragging
    const ViewPoint now = controls.camera().view();
    EXPECT_LT((now.eye - before.eye).norm(), 1e-12) << i;
    EXPECT_LT((now.target - before.target).norm(), 1e-12) << i;
    EXPECT_LT((pixelOf(controls.cueBall().head<2>()) - cursor).norm(), 0.05) << i;
  }
  controls.mouseButton(MouseButton::Left, false, a.x() + 240, a.y() - 100);
  EXPECT_FALSE(controls.draggingCueBall());
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  EXPECT_LT((controls.camera().view().target - controls.cueBall()).norm(), 1e-12);
}

TEST_F(BallInHandTest, AtAPracticeTableAnyBallIsDraggedAndLetGoOnce) {
  controls.startTurn(Eigen::Vector3d(-0.8, 0.0, kRadius), rules::BallInHand::Anywhere);
  controls.setClickTargets({{{3, Eigen::Vector2d(0.2, 0.1)}}, {}});
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  // Off (a match), a press on the 3 turns the cue; on, it picks the 3 up.
  const Eigen::Vector2d a = pixelOf(Eigen::Vector2d(0.2, 0.1));
  const Eigen::Vector2d b = pixelOf(Eigen::Vector2d(0.4, -0.2));
  controls.mouseButton(MouseButton::Left, true, a.x(), a.y());
  EXPECT_FALSE(controls.draggedBall());
  controls.mouseButton(MouseButton::Left, false, a.x(), a.y());
  controls.setBallDragging(true);
  controls.mouseButton(MouseButton::Left, true, a.x(), a.y());
  ASSERT_TRUE(controls.draggedBall());
  EXPECT_EQ(controls.draggedBall()->first, 3);
  for (int i = 1; i <= 10; ++i) {
    const Eigen::Vector2d p = a + (b - a) * (i / 10.0);
    controls.mouseMove(p.x(), p.y());
  }
  EXPECT_FALSE(controls.takeBallMove());  // not before it is let go
  controls.mouseButton(MouseButton::Left, false, b.x(), b.y());
  const auto move = controls.takeBallMove();
  ASSERT_TRUE(move);
  EXPECT_EQ(move->first, 3);
  EXPECT_LT((move->second - Eigen::Vector2d(0.4, -0.2)).norm(), 0.003);
  EXPECT_FALSE(controls.takeBallMove());
  EXPECT_FALSE(controls.draggedBall());
  // A press that does not move stays a click (a call), not a move.
  controls.mouseButton(MouseButton::Left, true, a.x(), a.y());
  controls.mouseButton(MouseButton::Left, false, a.x(), a.y());
  EXPECT_FALSE(controls.takeBallMove());
}

// A slip found in play: with "call: a safety" showing, clicking the 8 and pressing C left a call
// with a pocket and no ball (the HUD then read "none needed on the break").
TEST_F(BallInHandTest, CAfterClickingABallCallsThatBallAndWithNoBallChangesNothing) {
  controls.startTurn(Eigen::Vector3d(-0.8, 0.0, kRadius), rules::BallInHand::None);
  controls.setClickTargets({{{8, Eigen::Vector2d(0.2, 0.1)}}, {}});
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  controls.suggestCall({.ball = std::nullopt, .pocket = "", .safety = true});
  controls.keyDown(Key::C, {});  // nothing called: no pocket to move on
  EXPECT_TRUE(controls.aim().call.safety);
  EXPECT_FALSE(controls.aim().call.ball);
  const Eigen::Vector2d eight = pixelOf(Eigen::Vector2d(0.2, 0.1));
  controls.mouseButton(MouseButton::Left, true, eight.x(), eight.y());
  controls.mouseButton(MouseButton::Left, false, eight.x(), eight.y());
  ASSERT_EQ(controls.pickedBall(), 8);
  controls.keyDown(Key::C, {});
  EXPECT_EQ(controls.aim().call.ball, 8);
  EXPECT_FALSE(controls.aim().call.pocket.empty());
  EXPECT_FALSE(controls.aim().call.safety);
  EXPECT_FALSE(controls.pickedBall());
}

TEST_F(BallInHandTest, TheBallThenThePocketUnderTheCursorAreWhatAClickWouldCall) {
  // A pocket's mouth within 15 cm of the point under the cursor calls it (kPocketReach); the
  // foot right corner's mouth at (1.27, 0.635) and the 8 at (0.2, 0.1), both in view.
  controls.startTurn(Eigen::Vector3d(-0.8, 0.0, kRadius), rules::BallInHand::None);
  controls.setClickTargets(
      {{{8, Eigen::Vector2d(0.2, 0.1)}}, {{"foot_right_corner", Eigen::Vector2d(1.22, 0.585)}}});
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  const Eigen::Vector2d eight = pixelOf(Eigen::Vector2d(0.2, 0.1));
  const Eigen::Vector2d pocket = pixelOf(Eigen::Vector2d(1.22, 0.585));
  const Eigen::Vector2d felt = pixelOf(Eigen::Vector2d(0.6, -0.3));
  controls.mouseMove(felt.x(), felt.y());
  EXPECT_FALSE(controls.hovered()) << "open felt";
  controls.mouseMove(pocket.x(), pocket.y());
  EXPECT_FALSE(controls.hovered()) << "a pocket calls nothing before a ball is picked";
  controls.mouseMove(eight.x(), eight.y());
  auto target = controls.hovered();
  ASSERT_TRUE(target);
  EXPECT_EQ(target->ball, 8);
  EXPECT_LT((target->at - Eigen::Vector2d(0.2, 0.1)).norm(), 1e-12);
  controls.mouseButton(MouseButton::Left, true, eight.x(), eight.y());
  EXPECT_FALSE(controls.hovered()) << "nothing while the button is down";
  controls.mouseButton(MouseButton::Left, false, eight.x(), eight.y());
  ASSERT_EQ(controls.pickedBall(), 8);
  controls.mouseMove(pocket.x(), pocket.y());
  target = controls.hovered();
  ASSERT_TRUE(target);
  EXPECT_FALSE(target->ball);
  EXPECT_EQ(target->pocket, "foot_right_corner");
  // The click there calls what was ringed.
  controls.mouseButton(MouseButton::Left, true, pocket.x(), pocket.y());
  controls.mouseButton(MouseButton::Left, false, pocket.x(), pocket.y());
  EXPECT_EQ(controls.aim().call.ball, 8);
  EXPECT_EQ(controls.aim().call.pocket, "foot_right_corner");
  controls.stopAiming();
  EXPECT_FALSE(controls.hovered()) << "nothing to call while watching";
}

// Snooker nominates a ball and never a pocket (Section 3, "Nominated Ball"); the rules refuse a
// called pocket in snooker, and a click at a pocket used to send one.
TEST_F(BallInHandTest, InSnookerAClickNominatesTheBallAloneAndNoPocketIsCalled) {
  controls.startTurn(Eigen::Vector3d(-0.8, 0.0, kRadius), rules::BallInHand::None);
  // On a colour: the green may be nominated, the red (the 3) may not.
  controls.setClickTargets(
      {{{17, Eigen::Vector2d(0.2, 0.1)}, {3, Eigen::Vector2d(0.4, -0.2)}}, {}});
  controls.setNominable(std::vector<int>{17});
  for (int i = 0; i < 60; ++i) controls.advance(1.0 / 60);
  const auto click = [&](const Eigen::Vector2d& at) {
    const Eigen::Vector2d p = pixelOf(at);
    controls.mouseButton(MouseButton::Left, true, p.x(), p.y());
    controls.mouseButton(MouseButton::Left, false, p.x(), p.y());
  };
  click({0.4, -0.2});
  EXPECT_FALSE(controls.aim().call.ball) << "a red is not nominated";
  EXPECT_FALSE(controls.pickedBall());
  click({0.2, 0.1});
  EXPECT_EQ(controls.aim().call.ball, 17);
  EXPECT_TRUE(controls.aim().call.pocket.empty());
  EXPECT_FALSE(controls.pickedBall()) << "no pocket to wait for";
  controls.keyDown(Key::C, {});  // no pocket to call
  controls.keyDown(Key::K, {});  // no safety to declare
  EXPECT_TRUE(controls.aim().call.pocket.empty());
  EXPECT_FALSE(controls.aim().call.safety);
  // The nomination clicked again is dropped; once more, it is back.
  click({0.2, 0.1});
  EXPECT_FALSE(controls.aim().call.ball);
  click({0.2, 0.1});
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_EQ(shot->called_ball, 17);
  EXPECT_TRUE(shot->called_pocket.empty());
  EXPECT_FALSE(shot->safety);
  EXPECT_TRUE(wireCheck(*shot).ok()) << wireCheck(*shot).error();
}

TEST_F(BallInHandTest, BehindTheHeadStringTheDragStopsAtIt) {
  controls.startTurn(Eigen::Vector3d(-0.8, 0.0, kRadius), rules::BallInHand::BehindHeadString);
  drag(Eigen::Vector2d(-0.8, 0.0), Eigen::Vector2d(-0.5, 0.0));
  ASSERT_TRUE(controls.aim().cue_ball_at);
  EXPECT_LT(controls.aim().cue_ball_at->x(), PlacementArea{}.head_string_x);
  EXPECT_GT(controls.aim().cue_ball_at->x(), PlacementArea{}.head_string_x - 0.02);
}

// Snooker's cue ball in hand goes in the D (Section 3, 9): a drag out past its arc or over the
// baulk line stops on the arc, where the rules accept it.
TEST_F(BallInHandTest, InTheDTheDragStaysInTheD) {
  auto loaded = game::loadTable("snooker-12ft");
  ASSERT_TRUE(loaded) << loaded.error();
  ASSERT_TRUE(loaded->context.snooker);
  const table::SnookerSpots marks = *loaded->context.snooker;
  PlacementArea area;
  area.half_length = loaded->halfLength();
  area.half_width = loaded->halfWidth();
  area.ball_radius = loaded->radius();
  area.d_centre = marks.brown;
  area.d_radius = marks.d_radius;
  controls.setTable(protocol::CommandLimits{}, area,
                    CameraRig(loaded->spec.length, loaded->spec.width, 1280.0 / 720.0));
  controls.setViewport(1280, 720);
  // Each target's nearest point of the D: over the baulk line, the line beside it; beyond the
  // arc, the arc toward it.
  const Eigen::Vector2d beyond(marks.baulk_x - 0.6, -0.5);
  const Eigen::Vector2d on_arc = marks.brown + (beyond - marks.brown).normalized() * marks.d_radius;
  for (const auto& [target, nearest] :
       {std::pair{Eigen::Vector2d(marks.baulk_x + 0.4, 0.1), Eigen::Vector2d(marks.baulk_x, 0.1)},
        std::pair{beyond, on_arc}}) {
    controls.startTurn(Eigen::Vector3d(marks.brown.x(), marks.brown.y(), area.ball_radius),
                       rules::BallInHand::InTheD);
    drag(marks.brown, target);
    ASSERT_TRUE(controls.aim().cue_ball_at);
    const Eigen::Vector2d at = *controls.aim().cue_ball_at;
    EXPECT_TRUE(table::inTheD(marks, at)) << at.transpose();
    EXPECT_TRUE(
        rules::checkCueBallPlacement(rules::BallInHand::InTheD, at, {}, loaded->context).ok());
    EXPECT_LT((at - nearest).norm(), 0.01) << at.transpose() << " for " << target.transpose();
  }
  // Inside the D it goes where the mouse puts it.
  const Eigen::Vector2d inside(marks.baulk_x - 0.1, 0.12);
  controls.startTurn(Eigen::Vector3d(marks.brown.x(), marks.brown.y(), area.ball_radius),
                     rules::BallInHand::InTheD);
  drag(marks.brown, inside);
  ASSERT_TRUE(controls.aim().cue_ball_at);
  EXPECT_LT((*controls.aim().cue_ball_at - inside).norm(), 0.005);
}

TEST_F(BallInHandTest, WithoutBallInHandAPressOnTheCueBallTurnsTheCue) {
  controls.startTurn(Eigen::Vector3d(0.2, 0.0, kRadius), rules::BallInHand::None);
  const Eigen::Vector2d a = pixelOf(Eigen::Vector2d(0.2, 0.0));
  controls.mouseButton(MouseButton::Left, true, a.x(), a.y());
  EXPECT_FALSE(controls.draggingCueBall());
  const auto shot = shoot(controls, 0.2);
  ASSERT_TRUE(shot);
  EXPECT_FALSE(shot->cue_ball_at);
}

}  // namespace
}  // namespace pool::app::test
