// Stronge's compliant cushion model against his closed forms, and pooltool 0.6's stun-ball rebound.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fixtures.h"
#include "physics/ball_cushion/cushion_model.h"

namespace pool::physics::test {
namespace {

const Vec3 kNormal(0.0, -1.0, 0.0);  // a cushion along x at the ball's +y side, at the equator
constexpr double kBetaT = 3.5;       // a sphere's tangential inverse mass coefficient (β_n = 1)

Vec3 contactVelocity(const Vec3& v, const Vec3& w, const Vec3& n, double R) {
  return v + w.cross(-R * n);
}

/// The normal from a nose `lift` above the centre of a ball on the slate (at its +y side).
Vec3 noseNormal(double lift, double R) {
  const double s = lift / R;
  return Vec3(0.0, -std::sqrt(1.0 - s * s), -s);
}

/// Stronge's slip-stick-slip solution in closed form (Stronge, Impact Mechanics, ch. 5: a sphere
/// on a compliant half-space, springs k_n and k_t, unloading stiffness k_n/e²), for an impact
/// whose initial slip stops during compression. Time in units of 1/ω_n; approach speed V,
/// initial slip s0 > 0. Returns the final tangential contact velocity (along the initial slip).
double slipStickSlipFinalSlip(double V, double s0, double mu, double e, double ratio) {
  const double kt = ratio * ratio / kBetaT;  // k_t/k_n, from ω_t²/ω_n² = β_t·k_t/(β_n·k_n)
  const double eta2 = 1.0 / kt;              // Stronge's η² = (β_t/β_n)/(ω_t/ω_n)²
  const double tc = 0.5 * std::numbers::pi, tf = (1.0 + e) * tc;
  auto force = [&](double t) {  // normal force per unit mass
    return t <= tc ? V * std::sin(t) : V * std::sin(t / e + tc * (1.0 - 1.0 / e));
  };
  // Initial slip: the spring sits at the friction limit; the slip stops where the contact's
  // velocity equals the rate of the spring's stretch, μ·η²·V·cos t.
  const double x = (s0 / (mu * V) - kBetaT) / (eta2 - kBetaT);
  EXPECT_TRUE(x > 0.0 && x < 1.0) << "the stick must begin during compression";
  const double ts = std::acos(x);
  const double us = s0 - mu * kBetaT * V * (1.0 - std::cos(ts));
  const double xis = mu * force(ts) / kt;
  // Stuck: the contact oscillates at ω_t = ratio·ω_n until the spring's force reaches μ·F again.
  auto xi = [&](double t) {
    return xis * std::cos(ratio * (t - ts)) + us / ratio * std::sin(ratio * (t - ts));
  };
  auto ut = [&](double t) {
    return us * std::cos(ratio * (t - ts)) - ratio * xis * std::sin(ratio * (t - ts));
  };
  auto excess = [&](double t) { return kt * std::abs(xi(t)) - mu * force(t); };
  double lo = ts + 1e-6, hi = lo;
  const double step = 1e-4;
  while (hi < tf && excess(hi) <= 0.0) {
    lo = hi;
    hi += step;
  }
  if (hi >= tf) return ut(tf);  // stuck to the end
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) <= 0.0 ? lo : hi) = mid;
  }
  const double tslip = hi;
  // Final slip: the spring's force μ·F against its stretch, integrated to the end of the impact.
  const double phase = tslip / e + tc * (1.0 - 1.0 / e);
  const double impulse = V * e * (1.0 + std::cos(phase));  // ∫ F dt from tslip to tf
  return ut(tslip) - std::copysign(mu * kBetaT * impulse, xi(tslip));
}

/// A stun ball (no spin) of speed 1 m/s arriving `incidence` from the normal on a cushion whose
/// contact normal is `n`: the horizontal rebound angle from the normal, in degrees, from the
/// closed-form contact velocities.
double closedFormRebound(double incidence, const Vec3& n, const table::PhysicsParams& p,
                         double ratio) {
  const Vec3 v(std::sin(incidence), std::cos(incidence), 0.0);
  const double un = v.dot(n);
  const Vec3 slip = v - un * n;
  const double s0 = slip.norm();
  const double uf = slipStickSlipFinalSlip(-un, s0, p.u_c, p.e_c, ratio);
  // Δu_n = (1 + e)·V with β_n = 1; Δu_t = β_t·P_t/m.
  Vec3 out = v + (1.0 + p.e_c) * (-un) * n + (uf - s0) / kBetaT * (slip / s0);
  out.z() = 0.0;
  return std::atan2(out.x(), -out.y()) / kDeg;
}

double modelRebound(double incidence, const Vec3& n, const table::PhysicsParams& p, double ratio) {
  const auto model = makeCushionStrongeCompliant(p, ratio);
  Vec3 v(std::sin(incidence), std::cos(incidence), 0.0), w = Vec3::Zero();
  model->resolve(v, w, n, p.e_c, true);
  EXPECT_EQ(v.z(), 0.0) << "a ball on the slate keeps no vertical speed";
  return std::atan2(v.x(), -v.y()) / kDeg;
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
// μ((1 + e)β_t/β_n − η²/e), here 1.04 with ω_t/ω_n = 1.8): the tangential contact velocity falls
// by exactly μ·β_t·(1 + e)·|u_n0|, with β_t = 7/2 for a sphere.
TEST(CushionStronge, GrossSlipLosesMuBetaOnePlusETimesTheNormalSpeed) {
  const table::PhysicsParams p;
  const auto model = makeCushionStrongeCompliant(p);
  const double R = p.ball_radius;
  Vec3 v(2.0, 1.0, 0.0), w = Vec3::Zero();
  model->resolve(v, w, kNormal, p.e_c, true);
  const Vec3 u = contactVelocity(v, w, kNormal, R);
  EXPECT_NEAR(u.x(), 2.0 - p.u_c * 3.5 * (1.0 + p.e_c) * 1.0, 1e-3);
  EXPECT_NEAR(u.y(), -p.e_c * 1.0, 1e-3);
}

// The same closed form at the nose, along the tilted normal: the contact's slip (which now has a
// vertical part) falls by μ·β_t·(1 + e)·|u_n0| along its own direction, and the normal contact
// velocity comes back scaled by e, before the slate takes the vertical speed.
TEST(CushionStronge, GrossSlipAtTheNoseActsAlongTheTiltedNormal) {
  table::PhysicsParams p;
  const double R = p.ball_radius;
  const Vec3 n = noseNormal(p.cushion_height - R, R);
  const auto model = makeCushionStrongeCompliant(p);
  const Vec3 v0(2.0, 1.0, 0.0), w0 = Vec3::Zero();
  Vec3 v = v0, w = w0;
  model->resolve(v, w, n, p.e_c, /*on_slate=*/false);  // airborne: the vertical speed is kept
  const Vec3 u0 = contactVelocity(v0, w0, n, R);
  const double un0 = u0.dot(n);
  const Vec3 s0 = u0 - un0 * n;
  const Vec3 u = contactVelocity(v, w, n, R);
  EXPECT_NEAR(u.dot(n), -p.e_c * un0, 1e-3);
  const Vec3 expected = s0 * (1.0 - p.u_c * 3.5 * (1.0 + p.e_c) * (-un0) / s0.norm());
  EXPECT_NEAR((u - u.dot(n) * n - expected).norm(), 0.0, 1e-3);
}

// Closed form with friction too high to slip: the tangential springs carry the contact through
// the whole impact, so its tangential velocity oscillates at ω_t = 1.8·ω_n, over a contact of
// (1 + e)·π/(2ω_n): u_t,f = u_t0·cos(1.8·(1 + e)·π/2), here −0.51·u_t0 (the slip reverses).
TEST(CushionStronge, StuckContactOscillatesAtTheTangentialFrequency) {
  table::PhysicsParams p;
  p.u_c = 100.0;
  const auto model = makeCushionStrongeCompliant(p);
  Vec3 v(0.3, 1.0, 0.0), w = Vec3::Zero();
  model->resolve(v, w, kNormal, p.e_c, true);
  const double expected =
      0.3 * std::cos(kStrongeFrequencyRatio * (1.0 + p.e_c) * std::numbers::pi / 2.0);
  EXPECT_NEAR(contactVelocity(v, w, kNormal, p.ball_radius).x(), expected, 2e-3);
}

// Stronge's slip-stick-slip solution (stick time in closed form, then the root where the spring
// force reaches μ times the normal force again) for a stun ball 30° from the normal, e 0.85,
// μ 0.2, at the equator and at the nose, for pooltool's two frequency ratios (1.7, its model's
// default; 1.8, its resolver's). They agree to 1e-4°; 0.001° allows for the time steps, which
// resolve the stick and slip instants to π/800 of ω_n·t.
TEST(CushionStronge, StunBallMatchesTheSlipStickSlipSolution) {
  const table::PhysicsParams p;
  const double R = p.ball_radius;
  const double a = 30.0 * kDeg;
  for (const double ratio : {1.7, 1.8}) {
    for (const Vec3& n : {kNormal, noseNormal(p.cushion_height - R, R)}) {
      SCOPED_TRACE(testing::Message() << "ratio " << ratio << ", normal z " << n.z());
      EXPECT_NEAR(modelRebound(a, n, p, ratio), closedFormRebound(a, n, p, ratio), 0.001);
    }
  }
}

// pooltool 0.6 (its default resolver: Stronge compliant, ω_t/ω_n 1.8, the contact at the nose
// along the 3-D normal, the vertical speed dropped) with this table's coefficients and nose
// height rebounds a stun ball arriving at 30° at 24.0° from the normal. The older equatorial
// contact with ratio 1.7 gave 20.7°: the nose's tilt and the stiffer tangential spring are the
// whole difference.
TEST(CushionStronge, StunBallAtThirtyDegreesReboundsAsPooltoolDoes) {
  const table::PhysicsParams p;
  const double R = p.ball_radius;
  const Vec3 n = noseNormal(p.cushion_height - R, R);
  EXPECT_NEAR(modelRebound(30.0 * kDeg, n, p, kStrongeFrequencyRatio), 24.0, 0.1);
  EXPECT_NEAR(modelRebound(30.0 * kDeg, kNormal, p, 1.7), 20.7, 0.1);
}

}  // namespace
}  // namespace pool::physics::test
