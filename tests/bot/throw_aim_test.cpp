// Aiming off for throw: a slow cut leaves off its ghost-ball line by the throw the ball–ball
// friction gives it, and the corrected cue line sends the object ball along its line and into the
// pocket the uncorrected one misses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/plan_context.h"
#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/throw_aim.h"
#include "support/ai_fixture.h"

namespace pool::bot::test {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A 30° cut of ball 1, `distance` m from the foot left corner's mouth, the cue ball 0.6 m from the
// ghost ball: its pot line.
struct Cut {
  std::vector<physics::Ball> balls;
  PotLine line;
};

Cut thirtyDegreeCut(double distance = 0.5) {
  const auto& view = nineFoot();
  const int pocket = pocketIndex(view, "foot_left_corner");
  const Vec2 mouth = view.pockets[static_cast<std::size_t>(pocket)].mouth;
  const Vec2 object = onPocketLine("foot_left_corner", Vec2(0.0, 0.0), distance);
  const Vec2 d = (mouth - object).normalized();
  const Vec2 ghost = object - 2 * view.radius() * d;
  const double turn = 30.0 * kDegree;
  const Vec2 aim(std::cos(turn) * d.x() - std::sin(turn) * d.y(),
                 std::sin(turn) * d.x() + std::cos(turn) * d.y());
  const Vec2 cue = ghost - 0.6 * aim;
  Cut cut{layout({resting(0, cue.x(), cue.y()), resting(1, object.x(), object.y())}), {}};
  const auto line = potLine(cue, object, 1, pocket, view);
  if (line) cut.line = *line;
  return cut;
}

// The angle (rad) from `line`'s ghost-ball direction to where `shot` sends its ball in the physics.
double offLine(ShotVerifier& verifier, const Cut& cut, const PlannedShot& shot) {
  const auto heading = verifier.heading(cut.balls, shot, cut.line.ball, 3.0);
  EXPECT_TRUE(heading.has_value());
  if (!heading) return 1.0;
  return angleBetween(angleOf(*heading), angleOf(cut.line.object - cut.line.ghost));
}

// A centre-ball stroke along `line` at `speed` (m/s) called into the foot left corner. At 1 m/s,
// after 0.6 m of cloth, the cue ball arrives rolling at about 0.65 m/s.
PlannedShot centreBall(const PotLine& line, double speed = 1.0) {
  PlannedShot shot;
  shot.kind = ShotKind::Pot;
  shot.cue = stroke(line.yaw, speed, 0.0);
  shot.called_ball = line.ball;
  shot.called_pocket = "foot_left_corner";
  return shot;
}

TEST(ThrowAim, ASlowCutIsThrownOffItsLineAndTheCorrectionPutsItBack) {
  const auto& view = nineFoot();
  const Cut cut = thirtyDegreeCut();
  ASSERT_NEAR(cut.line.cut, 30.0 * kDegree, 1e-6);
  ShotVerifier verifier(view);
  PlannedShot shot = centreBall(cut.line);
  // Cut-induced throw (Alciatore, TP A-14: a stun 30° cut throws about 4–5° at 0.45 m/s and 1.5°
  // at 3 m/s, a rolling cue ball about half as much): the object ball leaves at least 1° off the
  // line of centres, turned toward the cue ball's own direction (less cut).
  const double before = offLine(verifier, cut, shot);
  EXPECT_GT(std::abs(before), 1.0 * kDegree);
  const double toward_cue = angleBetween(angleOf(cut.line.ghost - cut.line.cue),
                                         angleOf(cut.line.object - cut.line.ghost));
  EXPECT_GT(before * toward_cue, 0.0) << "thrown away from the cue ball's direction";
  // One probe and one step: the ball leaves within 0.1° of its line (a tenth of the throw).
  PlanContext context{view, verifier, cut.balls, solidsToShoot(), solidsToShoot(), {}, 2};
  aimForThrow(context, shot, cut.line);
  EXPECT_EQ(context.runs_left, 1);
  EXPECT_LT(std::abs(offLine(verifier, cut, shot)), 0.1 * kDegree);
}

TEST(ThrowAim, TheCorrectedLinePotsALongCutTheGhostBallMisses) {
  const auto& view = nineFoot();
  // 1.5 m from the mouth, 1° of throw is about 26 mm at the pocket: about what a corner takes.
  // Struck at three quarters of the pot's speed (potSpeed): the ball still reaches the pocket,
  // and slow enough to be thrown by more than 1°.
  const Cut cut = thirtyDegreeCut(1.5);
  ShotVerifier verifier(view);
  const auto state = solidsToShoot();
  PlannedShot shot = centreBall(cut.line, 0.75 * potSpeed(cut.line, view.spec.params));
  // The whole shot in the physics, judged by the rules: the ghost-ball line misses.
  const Trial ghost = verifier.run(cut.balls, state, shot);
  ASSERT_TRUE(ghost.judged) << ghost.error;
  EXPECT_FALSE(ghost.potted_call);
  PlanContext context{view, verifier, cut.balls, state, state, {}, 1};
  aimForThrow(context, shot, cut.line);
  const Trial aimed = verifier.run(cut.balls, state, shot);
  ASSERT_TRUE(aimed.judged) << aimed.error;
  EXPECT_TRUE(aimed.potted_call);
}

TEST(ThrowAim, WithTheBudgetSpentTheLineIsLeftAlone) {
  const auto& view = nineFoot();
  const Cut cut = thirtyDegreeCut();
  ShotVerifier verifier(view);
  PlannedShot shot = centreBall(cut.line);
  PlanContext context{view, verifier, cut.balls, solidsToShoot(), solidsToShoot(), {}, 0};
  aimForThrow(context, shot, cut.line);
  EXPECT_EQ(shot.cue.yaw, cut.line.yaw);
  EXPECT_EQ(verifier.runs(), 0);
}

}  // namespace
}  // namespace pool::bot::test
