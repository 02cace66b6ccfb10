// Stronge's compliant cushion model against its closed forms and pooltool's rebound of a stun ball.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fixtures.h"
#include "physics/ball_cushion/cushion_model.h"

namespace pool::physics::test {
namespace {

const Vec3 kNormal(0.0, -1.0, 0.0);  // a cushion along x at the ball's +y side

Vec3 contactVelocity(const Vec3& v, const Vec3& w, double R) {
  return v + w.cross(-R * kNormal);
}

// Closed form without friction: the normal velocity comes back scaled by e (Stronge's unloading
// stiffness k/e² returns e² of the stored energy). 1e-4 relative: the time steps end the contact
// within one step of zero force, where the force is nearly zero.
TEST(CushionStronge, FrictionlessReturnsENormalSpeed) {
  table::PhysicsParams p;
  p.u_c = 0.0;
  const auto model = makeCushionStrongeCompliant(p);
  Vec3 v(0.5, 1.2, 0.0), w(3.0, -4.0, 20.0);
  const Vec3 w0 = w;
  model->resolve(v, w, kNormal, p.e_c, true);
  EXPECT_NEAR(v.y(), -p.e_c * 1.2, 1e-4 * 1.2);
  EXPECT_NEAR(v.x(), 0.5, 1e-12);
  EXPECT_NEAR((w - w0).norm(), 0.0, 1e-12);
}

// Gross slip (Stronge's case of a slip that never stops: u_t0/|u_n0| above
// μ((1 + e)β_t/β_n − η²/e), here 1.01): the tangential contact velocity falls by exactly
// μ·β_t·(1 + e)·|u_n0|, with β_t = 7/2 for a sphere.
TEST(CushionStronge, GrossSlipLosesMuBetaOnePlusETimesTheNormalSpeed) {
  const table::PhysicsParams p;
  const auto model = makeCushionStrongeCompliant(p);
  const double R = p.ball_radius;
  Vec3 v(2.0, 1.0, 0.0), w = Vec3::Zero();
  model->resolve(v, w, kNormal, p.e_c, true);
  const Vec3 u = contactVelocity(v, w, R);
  EXPECT_NEAR(u.x(), 2.0 - p.u_c * 3.5 * (1.0 + p.e_c) * 1.0, 1e-3);
  EXPECT_NEAR(u.y(), -p.e_c * 1.0, 1e-3);
}

// Closed form with friction too high to slip: the tangential springs carry the contact through
// the whole impact, so its tangential velocity oscillates at ω_t = 1.7·ω_n, over a contact of
// (1 + e)·π/(2ω_n): u_t,f = u_t0·cos(1.7·(1 + e)·π/2), here −0.229·u_t0 (the slip reverses).
TEST(CushionStronge, StuckContactOscillatesAtTheTangentialFrequency) {
  table::PhysicsParams p;
  p.u_c = 100.0;
  const auto model = makeCushionStrongeCompliant(p);
  Vec3 v(0.3, 1.0, 0.0), w = Vec3::Zero();
  model->resolve(v, w, kNormal, p.e_c, true);
  const double expected = 0.3 * std::cos(1.7 * (1.0 + p.e_c) * std::numbers::pi / 2.0);
  EXPECT_NEAR(contactVelocity(v, w, p.ball_radius).x(), expected, 2e-3);
}

// Stronge's slip-stick-slip solution (stick time, then the root where the spring force reaches
// μ times the normal force again), evaluated from its closed-form pieces for a stun ball 30° from
// the normal with e 0.85, μ 0.2, frequency ratio 1.7: the ball leaves 20.685° from the normal.
// 0.05°: the time steps resolve the stick and slip instants to π/800 of ω_n·t.
TEST(CushionStronge, StunBallAtThirtyDegreesMatchesTheSlipStickSlipSolution) {
  const table::PhysicsParams p;
  const auto model = makeCushionStrongeCompliant(p);
  const double a = 30.0 * kDeg;
  Vec3 v(std::sin(a), std::cos(a), 0.0), w = Vec3::Zero();
  model->resolve(v, w, kNormal, p.e_c, true);
  EXPECT_NEAR(std::atan2(v.x(), -v.y()) / kDeg, 20.685, 0.05);
}

}  // namespace
}  // namespace pool::physics::test
