// The time-of-impact root finder (earliestClosing) against polynomials with known roots: simple,
// double, triple, a local minimum short of zero, and gaps that start closed.
#include "physics/polynomial.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "core/split_mix64.h"

namespace pool::physics {
namespace {

/// Coefficients (low order first) of (t − r1)(t − r2)(t − r3)(t − r4), for known roots.
Quartic fromRoots(double r1, double r2, double r3, double r4) {
  // Elementary symmetric polynomials of the roots.
  const double e1 = r1 + r2 + r3 + r4;
  const double e2 = r1 * r2 + r1 * r3 + r1 * r4 + r2 * r3 + r2 * r4 + r3 * r4;
  const double e3 = r1 * r2 * r3 + r1 * r2 * r4 + r1 * r3 * r4 + r2 * r3 * r4;
  const double e4 = r1 * r2 * r3 * r4;
  return {e4, -e3, e2, -e1, 1.0};
}

// Simple roots of polynomials with coefficients of order 1..100: the solver brackets a root to
// 1e-13 s and rounding in the evaluation moves a simple root by about 1e-15 s, so 1e-12 s is ten
// brackets of margin and still far below any difference between the roots used here.
constexpr double kSimpleRootTolerance = 1e-12;

TEST(Polynomial, EvaluateIsTheQuarticAtT) {
  const Quartic p{1.0, -2.0, 3.0, -4.0, 5.0};
  // 1 − 2·2 + 3·4 − 4·8 + 5·16 = 57, exact in doubles.
  EXPECT_EQ(evaluate(p, 2.0), 57.0);
  EXPECT_EQ(evaluate(p, 0.0), 1.0);
}

TEST(Polynomial, LinearGapClosesAtItsRoot) {
  // 0.3 − 0.6 t: zero at t = 0.5.
  EXPECT_NEAR(earliestClosing({0.3, -0.6, 0.0, 0.0, 0.0}, 10.0), 0.5, kSimpleRootTolerance);
  // Opening (growing) gap: never closes.
  EXPECT_EQ(earliestClosing({0.3, 0.6, 0.0, 0.0, 0.0}, 10.0), kNever);
}

TEST(Polynomial, QuadraticWithTwoRootsGivesTheFirst) {
  // (t − 1.5)(t − 4) = t² − 5.5 t + 6.
  EXPECT_NEAR(earliestClosing({6.0, -5.5, 1.0, 0.0, 0.0}, 10.0), 1.5, kSimpleRootTolerance);
  // −(t − 1.5)(t − 4) starts closed (−6) and opening; it is skipped until it closes again at 4.
  EXPECT_NEAR(earliestClosing({-6.0, 5.5, -1.0, 0.0, 0.0}, 10.0), 4.0, kSimpleRootTolerance);
}

TEST(Polynomial, RootsBeyondTheHorizonAreNotReported) {
  // (t − 1.5)(t − 4): the first root lies past t_max = 1.4.
  EXPECT_EQ(earliestClosing({6.0, -5.5, 1.0, 0.0, 0.0}, 1.4), kNever);
  EXPECT_EQ(earliestClosing({6.0, -5.5, 1.0, 0.0, 0.0}, 0.0), kNever);
}

TEST(Polynomial, QuarticWithFourRootsGivesTheSmallest) {
  // Roots 0.5, 1, 2, 3: positive at 0 (product 3 > 0), first down-crossing at 0.5.
  EXPECT_NEAR(earliestClosing(fromRoots(0.5, 1.0, 2.0, 3.0), 10.0), 0.5, kSimpleRootTolerance);
  // Roots 2.25, 2.5, 7, 8 (all past a local maximum at the start): the first is 2.25.
  EXPECT_NEAR(earliestClosing(fromRoots(2.25, 2.5, 7.0, 8.0), 10.0), 2.25, kSimpleRootTolerance);
}

TEST(Polynomial, LocalMinimumShortOfZeroIsNotAContact) {
  // (t² − 2t + 1.01)(t − 3)(t − 4): the first factor dips to 0.01 at t = 1 without a root, so the
  // gap comes close and opens again; the crossing is at 3.
  // (t² − 7t + 12)(t² − 2t + 1.01) = t⁴ − 9t³ + (12 + 14 + 1.01)t² − (24 + 7.07)t + 12.12.
  const Quartic p{12.12, -31.07, 27.01, -9.0, 1.0};
  EXPECT_NEAR(earliestClosing(p, 10.0), 3.0, kSimpleRootTolerance);
  EXPECT_GT(evaluate(p, 1.0), 0.0);
}

TEST(Polynomial, ExactDoubleRootIsATouchingContact) {
  // (t − 1)²: the gap reaches zero at t = 1 and opens again; every coefficient, the turning point
  // and the value there are exact in doubles, so the touch is found. Near a double root the
  // evaluation (1 − 2t + t², terms of order 1) rounds to zero once (t − 1)² falls under its
  // rounding of about 2.2e-16, i.e. within √2.2e-16 ≈ 1.5e-8 s of the root, and the solver may
  // stop anywhere there: the tolerance is 3e-8 s (15 nm at 1 m/s), and never after the touch.
  // (Where the turning point is not exactly representable a touch at zero separation may round
  // either way; it carries no impulse, so nothing depends on it. The near-double roots below are
  // the cases that matter.)
  const double t = earliestClosing({1.0, -2.0, 1.0, 0.0, 0.0}, 10.0);
  EXPECT_NEAR(t, 1.0, 3e-8);
  EXPECT_LE(t, 1.0 + kSimpleRootTolerance);
}

TEST(Polynomial, NearDoubleRootIsFoundOrMissedByTheSignOfTheOffset) {
  // (t − 1)² − ε has roots 1 ± √ε; (t − 1)² + ε has none. With ε = 1e-10 the pair of roots is
  // 2e-5 s apart. Rounding in the coefficients and evaluation is about 4e-16, far below ε, so the
  // sign of ε decides. At the root the slope is 2√ε = 2e-5, so a rounding of 4e-16 in the value
  // moves the root by 2e-11 s: the tolerance is 1e-10 s.
  constexpr double eps = 1e-10;
  EXPECT_NEAR(earliestClosing({1.0 - eps, -2.0, 1.0, 0.0, 0.0}, 10.0), 1.0 - std::sqrt(eps), 1e-10);
  EXPECT_EQ(earliestClosing({1.0 + eps, -2.0, 1.0, 0.0, 0.0}, 10.0), kNever);
}

TEST(Polynomial, NearDoubleRootInAQuarticIsFoundOrMissedByTheSignOfTheOffset) {
  // ((t − 1)² ∓ ε)(t − 3)(t − 4) = t⁴ − 9t³ + (27 ∓ ε)t² − (31 ∓ 7ε)t + 12(1 ∓ ε): a pair of
  // roots at 1 ± √ε, or none there, before the simple roots 3 and 4. With ε = 1e-8 the dip below
  // (or above) zero is 6ε = 6e-8 deep, against a rounding of the evaluation of about
  // 5·31·2.2e-16 ≈ 4e-14. The slope at 1 − √ε is about 2√ε·6 = 1.2e-3, so that rounding moves
  // the root by about 3e-11 s: the tolerance is 1e-10 s.
  constexpr double eps = 1e-8;
  const Quartic dips{12.0 * (1.0 - eps), -(31.0 - 7.0 * eps), 27.0 - eps, -9.0, 1.0};
  EXPECT_NEAR(earliestClosing(dips, 10.0), 1.0 - std::sqrt(eps), 1e-10);
  const Quartic stays{12.0 * (1.0 + eps), -(31.0 + 7.0 * eps), 27.0 + eps, -9.0, 1.0};
  EXPECT_NEAR(earliestClosing(stays, 10.0), 3.0, kSimpleRootTolerance);
}

TEST(Polynomial, TripleRootIsACrossing) {
  // (t − 1)³(t − 5) = t⁴ − 8t³ + 18t² − 16t + 5: positive at 0, negative on (1, 5). The derivative
  // has a double root at 1. Near 1 the quartic is about −4(t − 1)³, and its evaluation carries a
  // rounding of about 5·18·2.2e-16 ≈ 2e-14, so the computed crossing can sit anywhere within
  // (2e-14 / 4)^(1/3) ≈ 1.7e-5 s of 1: the tolerance is 5e-5 s.
  const Quartic p{5.0, -16.0, 18.0, -8.0, 1.0};
  EXPECT_NEAR(earliestClosing(p, 10.0), 1.0, 5e-5);
}

TEST(Polynomial, ClosedGapCountsOnlyWhileClosing) {
  // Already touching and closing: contact now.
  EXPECT_EQ(earliestClosing({0.0, -1.0, 0.0, 0.0, 0.0}, 10.0), 0.0);
  // Touching with zero slope and closing curvature: contact now.
  EXPECT_EQ(earliestClosing({0.0, 0.0, -1.0, 0.0, 0.0}, 10.0), 0.0);
  // A hair inside and opening (a contact just resolved): skipped, and it never closes again.
  EXPECT_EQ(earliestClosing({-1e-12, 1.0, 0.0, 0.0, 0.0}, 10.0), kNever);
  // A hair inside, opening, then turning back: −1e-12 + t − t²/4 has roots 2 ± 2√(1 − 1e-12),
  // about 1e-12 and 4; the first is the contact opening, the second its closing again.
  const double later = 2.0 + 2.0 * std::sqrt(1.0 - 1e-12);
  EXPECT_NEAR(earliestClosing({-1e-12, 1.0, -0.25, 0.0, 0.0}, 10.0), later, kSimpleRootTolerance);
}

// The shortcut that answers "never" when a gap is surely positive (its Bernstein coefficients on
// the interval) must never hide a contact: for 20000 random ball pairs, ones that touch and ones
// that pass within a few micrometres, a dense scan of the gap that finds it closed at some sample
// means earliestClosing found a contact no later than that sample, and a contact it finds has
// the gap closed there and open just before (the scan never disagrees).
TEST(Polynomial, SurelyPositiveShortcutHidesNoContact) {
  SplitMix64 rng(12);
  auto u = [&rng](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  int contacts = 0, misses = 0;
  for (int k = 0; k < 20000; ++k) {
    // Relative motion of two balls 2R = 0.05715 m apart at contact, apart at the start: a closest
    // approach near contact distance, along a curved path, within a horizon of up to 2 s.
    const double r = 0.05715;
    const double miss = r + (k % 2 == 0 ? u(-0.02, 0.0) : u(0.0, 1e-4));
    const double speed = u(0.05, 5.0);
    const double t_close = u(0.01, 1.5);
    const Eigen::Vector2d dir(std::cos(u(0, 6.3)), std::sin(u(0, 6.3)));
    const Eigen::Vector2d side(-dir.y(), dir.x());
    const Eigen::Vector2d dv = -speed * dir;
    const Eigen::Vector2d da = u(-0.5, 0.5) * dir + u(-0.5, 0.5) * side;
    // Position at t = 0 such that, without the acceleration, the closest approach is `miss`.
    const Eigen::Vector2d dp = miss * side + speed * t_close * dir;
    const Quartic p{dp.squaredNorm() - r * r, 2.0 * dp.dot(dv), dv.squaredNorm() + dp.dot(da),
                    dv.dot(da), 0.25 * da.squaredNorm()};
    if (!(p[0] > 0.0)) continue;  // apart at the start: the shortcut's case
    const double horizon = u(0.1, 2.0);
    const double t = earliestClosing(p, horizon);
    double first_closed = kNever;
    constexpr int kSamples = 4000;
    for (int i = 1; i <= kSamples; ++i) {
      const double ts = horizon * i / kSamples;
      if (evaluate(p, ts) <= 0.0) {
        first_closed = ts;
        break;
      }
    }
    if (first_closed < kNever) {
      ++contacts;
      ASSERT_LE(t, first_closed) << "pair " << k;
    } else {
      ++misses;
    }
    if (t < kNever) {
      EXPECT_LE(evaluate(p, t), 0.0) << "pair " << k;
      EXPECT_GT(evaluate(p, t - 1e-9), 0.0) << "pair " << k;
    }
  }
  // Both kinds were drawn in numbers.
  EXPECT_GT(contacts, 2000);
  EXPECT_GT(misses, 2000);
}

}  // namespace
}  // namespace pool::physics
