// The event predictors against closed forms: two balls head-on, a ball grazing another at ±1 nm
// from tangency, a ball reaching a cushion nose, a jaw point or a pocket's hole under friction, or
// stopping 1 µm short of a nose.
#include "physics/predict.h"

#include <gtest/gtest.h>

#include <cmath>

#include "table/physics_params.h"

namespace pool::physics {
namespace {

const table::PhysicsParams kParams{};
const double R = kParams.ball_radius;

/// The root t of x0 − v t + a t²/2 = 0 (a gap x0 closing at speed v, the closing slowed by a)
/// that comes first, in the form without cancellation: 2 x0 / (v + √(v² − 2 a x0)).
double firstClosing(double x0, double v, double a) {
  return 2.0 * x0 / (v + std::sqrt(v * v - 2.0 * a * x0));
}

// Contact times of gaps closing at 0.5..2 m/s over 0.1..1 m. The solver brackets a root to 1e-13 s;
// rounding of the gap's coefficients (about 1e-16 of a square metre) over the gap's slope at
// contact (4R times the closing speed, ≥ 0.05 m²/s) moves it by under 1e-14 s. 1e-12 s is ten
// brackets of margin, and a millionth of a millimetre at these speeds.
constexpr double kTimeTolerance = 1e-12;

TEST(PairContactTime, HeadOnAgainstABallAtRest) {
  // a rolls toward b along +x, slowed at u_r·g; contact when the centres are 2R apart.
  const double v = 1.5, L = 0.8;
  const double dec = kParams.u_r * kGravity;
  const Kinematics a{Vec3(0.0, 0.0, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const Kinematics b{Vec3(L, 0.0, R), Vec3::Zero(), Vec3::Zero()};
  const double expected = firstClosing(L - 2.0 * R, v, dec);
  EXPECT_NEAR(pairContactTime(a, b, R, 10.0), expected, kTimeTolerance);
  // The order of the balls does not matter.
  EXPECT_NEAR(pairContactTime(b, a, R, 10.0), expected, kTimeTolerance);
}

TEST(PairContactTime, HeadOnBothMovingAndSliding) {
  // Both slide toward each other at v, each slowed at u_s·g: the gap closes at 2v, slowed at
  // 2 u_s g.
  const double v = 2.0, L = 1.0;
  const double dec = kParams.u_s * kGravity;
  const Kinematics a{Vec3(0.0, 0.0, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const Kinematics b{Vec3(L, 0.0, R), Vec3(-v, 0.0, 0.0), Vec3(dec, 0.0, 0.0)};
  EXPECT_NEAR(pairContactTime(a, b, R, 10.0), firstClosing(L - 2.0 * R, 2.0 * v, 2.0 * dec),
              kTimeTolerance);
}

TEST(PairContactTime, NoContactWhenTheBallStopsShortOrTheHorizonEnds) {
  // Rolling from 0.8 m away at 0.3 m/s, slowed at u_r·g, it stops after v²/(2 u_r g) ≈ 0.46 m.
  const double v = 0.3, L = 0.8;
  const double dec = kParams.u_r * kGravity;
  ASSERT_LT(v * v / (2.0 * dec), L - 2.0 * R);
  const Kinematics a{Vec3(0.0, 0.0, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const Kinematics b{Vec3(L, 0.0, R), Vec3::Zero(), Vec3::Zero()};
  // The motion holds only until the ball stops (v / dec); the caller's horizon is that.
  EXPECT_EQ(pairContactTime(a, b, R, v / dec), kNever);
  // A reachable contact past the horizon is not reported either.
  const Kinematics fast{Vec3(0.0, 0.0, R), Vec3(1.0, 0.0, 0.0), Vec3::Zero()};
  const double t = (L - 2.0 * R) / 1.0;
  EXPECT_EQ(pairContactTime(fast, b, R, 0.99 * t), kNever);
  EXPECT_NEAR(pairContactTime(fast, b, R, 1.01 * t), t, kTimeTolerance);
}

/// A ball moving along +x at 1 m/s past a ball at rest at (L, d): contact iff d < 2R.
double grazeTime(double d) {
  const double L = 0.2;
  const Kinematics a{Vec3(0.0, 0.0, R), Vec3(1.0, 0.0, 0.0), Vec3::Zero()};
  const Kinematics b{Vec3(L, d, R), Vec3::Zero(), Vec3::Zero()};
  return pairContactTime(a, b, R, 10.0);
}

TEST(PairContactTime, NearTangentGrazeIsFoundOrMissedByOneNanometre) {
  // At an offset d = 2R − δ the balls touch when the x-distance is w = √(4R² − d²) =
  // √(δ (4R − δ)): about 11 µm for δ = 1 nm, so the contact comes 11 µs before the closest
  // approach. The gap's minimum, d² − 4R² ≈ ∓1.1e-10 m², is six orders of magnitude above the
  // rounding of its coefficients (about 1e-17 m²), so the sign of δ decides. At the root the gap
  // changes at 2·w·v ≈ 2e-5 m²/s, so that rounding moves the time by about 1e-12 s; the tolerance
  // is 1e-9 s, still 1e4 times smaller than the 11 µs that separate contact from closest approach.
  const double delta = 1e-9;
  const double d_in = 2.0 * R - delta;
  const double w = std::sqrt((2.0 * R - d_in) * (2.0 * R + d_in));
  EXPECT_NEAR(grazeTime(d_in), 0.2 - w, 1e-9);
  EXPECT_EQ(grazeTime(2.0 * R + delta), kNever);
}

/// One straight cushion nose along the y axis at x = x_nose, its playing side toward −x.
TableFeatures oneNose(double x_nose) {
  TableFeatures f;
  TableFeatures::Nose n;
  n.a = Vec2(x_nose, -1.0);
  n.dir = Vec2(0.0, 1.0);
  n.normal = Vec2(-1.0, 0.0);
  n.length = 2.0;
  n.name = "test_nose";
  f.noses.push_back(n);
  f.half_length = x_nose;
  f.half_width = 1.0;
  return f;
}

/// Horizontal distance from a ball's centre (on the slate) to the nose line at contact: the nose
/// at height h touches the sphere where √(R² − (h − R)²) from the centre.
double noseReach() {
  const double lift = kParams.cushion_height - R;
  return std::sqrt(R * R - lift * lift);
}

TEST(NextTableHit, BallSlidingIntoACushionUnderFriction) {
  // A ball on the slate slides toward the nose at 2 m/s, slowed at u_s·g; it touches when its
  // centre is noseReach() from the nose line.
  const double x_nose = 1.0, v = 2.0;
  const double dec = kParams.u_s * kGravity;
  const Kinematics k{Vec3(0.0, 0.3, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const TableHit hit = nextTableHit(k, false, oneNose(x_nose), R, kParams.cushion_height, 10.0);
  ASSERT_EQ(hit.kind, FeatureKind::Nose);
  EXPECT_EQ(hit.index, 0);
  EXPECT_NEAR(hit.t, firstClosing(x_nose - noseReach(), v, dec), kTimeTolerance);
  // The contact normal points from the nose back to the ball's centre: −x and up.
  const Vec3 n =
      contactNormal(k.at(hit.t), oneNose(x_nose), FeatureKind::Nose, 0, kParams.cushion_height);
  const double lift = kParams.cushion_height - R;
  EXPECT_NEAR(n.x(), -noseReach() / R, 1e-9);
  EXPECT_NEAR(n.z(), -lift / R, 1e-9);
}

TEST(NextTableHit, RollingBallStoppingJustShortOfTheCushionNeverReachesIt) {
  // Rolling at v, slowed at u_r·g, the ball travels v²/(2 u_r g) before stopping. With the nose
  // 1 µm beyond that, no contact; 1 µm nearer, contact close to the stop, at the closed form. The
  // gap's minimum, ±1 µm, is ten orders of magnitude above the rounding of its coefficients.
  // Near the stop the gap closes at only √(2 u_r g · 1 µm) ≈ 4.4e-4 m/s, so a rounding of 1e-16 m
  // moves the time by 2e-13 s: the tolerance is 1e-11 s.
  const double v = 0.8;
  const double dec = kParams.u_r * kGravity;
  const double travel = v * v / (2.0 * dec);
  const double stop_t = v / dec;
  const Kinematics k{Vec3(0.0, 0.0, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const double x_short = travel + noseReach() + 1e-6;
  EXPECT_EQ(nextTableHit(k, false, oneNose(x_short), R, kParams.cushion_height, stop_t).t, kNever);
  const double x_reach = travel + noseReach() - 1e-6;
  const TableHit hit = nextTableHit(k, false, oneNose(x_reach), R, kParams.cushion_height, stop_t);
  ASSERT_EQ(hit.kind, FeatureKind::Nose);
  EXPECT_NEAR(hit.t, firstClosing(x_reach - noseReach(), v, dec), 1e-11);
  EXPECT_LT(hit.t, stop_t);
}

TEST(NextTableHit, BallPassingBeyondTheNoseSegmentDoesNotHitIt) {
  // The nose spans y in [−1, 1]; a ball at y = 1.5 crosses its line but not the segment.
  const Kinematics k{Vec3(0.0, 1.5, R), Vec3(1.0, 0.0, 0.0), Vec3::Zero()};
  EXPECT_EQ(nextTableHit(k, false, oneNose(0.5), R, kParams.cushion_height, 10.0).t, kNever);
}

TEST(NextTableHit, BallRollingHeadOnIntoAJawPoint) {
  // A jaw point at nose height: a ball on the slate touches it when its centre is noseReach()
  // from the point horizontally, the same reach as for a nose line.
  const double v = 1.2, L = 0.5;
  const double dec = kParams.u_r * kGravity;
  TableFeatures f;
  f.points.push_back({Vec2(L, 0.0), "jaw_test"});
  const Kinematics k{Vec3(0.0, 0.0, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const TableHit hit = nextTableHit(k, false, f, R, kParams.cushion_height, 10.0);
  ASSERT_EQ(hit.kind, FeatureKind::Point);
  EXPECT_EQ(hit.index, 0);
  EXPECT_NEAR(hit.t, firstClosing(L - noseReach(), v, dec), kTimeTolerance);
}

TEST(NextTableHit, BallDropsWhenItsCentreCrossesTheHoleEdge) {
  // A ball rolling straight at a hole's centre drops when its centre is one hole radius away.
  const double v = 0.9, L = 0.4, hole_radius = 0.07;
  const double dec = kParams.u_r * kGravity;
  TableFeatures f;
  f.holes.push_back({Vec2(L, 0.0), hole_radius, "test_pocket"});
  const Kinematics k{Vec3(0.0, 0.0, R), Vec3(v, 0.0, 0.0), Vec3(-dec, 0.0, 0.0)};
  const TableHit hit = nextTableHit(k, false, f, R, kParams.cushion_height, 10.0);
  ASSERT_EQ(hit.kind, FeatureKind::Hole);
  EXPECT_NEAR(hit.t, firstClosing(L - hole_radius, v, dec), kTimeTolerance);
}

}  // namespace
}  // namespace pool::physics
