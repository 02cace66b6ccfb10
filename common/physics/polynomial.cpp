// Earliest down-crossing of a quartic: split the interval at the derivative's roots (recursively)
// into monotonic pieces, then bisect the first piece that crosses.
#include "physics/polynomial.h"

#include <algorithm>
#include <cmath>

namespace pool::physics {

namespace {

using Coeffs = std::array<double, 5>;

double evalDeg(const Coeffs& c, int deg, double t) {
  double v = 0.0;
  for (int i = deg; i >= 0; --i) v = v * t + c[static_cast<size_t>(i)];
  return v;
}

Coeffs derivative(const Coeffs& c, int deg) {
  Coeffs d{};
  for (int i = 1; i <= deg; ++i) d[static_cast<size_t>(i - 1)] = i * c[static_cast<size_t>(i)];
  return d;
}

/// A root of a polynomial known to be monotonic on [lo, hi] with f(lo), f(hi) of opposite
/// signs (or one zero): Newton steps kept inside the bracket, bisection when a step would leave
/// it, until the bracket is under 1e-13 s (a ball at 10 m/s moves 1 pm in that). Returns the end
/// on the side of hi's sign, so a gap found closing is closed (by a hair) at the time returned.
double bisect(const Coeffs& c, int deg, double lo, double hi) {
  constexpr double kTimeTolerance = 1e-13;
  const Coeffs d = derivative(c, deg);
  const bool lo_positive = evalDeg(c, deg, lo) > 0.0;
  double t = 0.5 * (lo + hi);
  for (int i = 0; i < 200; ++i) {
    const double f = evalDeg(c, deg, t);
    const bool at_lo = (f > 0.0) == lo_positive;
    (at_lo ? lo : hi) = t;
    if (hi - lo <= kTimeTolerance) break;
    const double df = evalDeg(d, deg - 1, t);
    const double step = df != 0.0 ? f / df : 0.0;
    double next = t - step;
    if (df == 0.0 || !(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    } else if (std::abs(step) < 0.5 * kTimeTolerance) {
      // Newton has converged from one side: probe a hair past the root to close the bracket.
      next = at_lo ? std::min(next + 0.5 * kTimeTolerance, 0.5 * (next + hi))
                   : std::max(next - 0.5 * kTimeTolerance, 0.5 * (next + lo));
    }
    t = next;
  }
  return hi;
}

/// Sorted real roots of the degree-`deg` polynomial strictly inside (lo, hi).
int rootsIn(const Coeffs& c, int deg, double lo, double hi, double* out) {
  while (deg > 0 && c[static_cast<size_t>(deg)] == 0.0) --deg;
  if (deg <= 0) return 0;
  if (deg == 1) {
    const double r = -c[0] / c[1];
    if (r > lo && r < hi) {
      out[0] = r;
      return 1;
    }
    return 0;
  }
  // Critical points split (lo, hi) into pieces where c is monotonic.
  double crit[4];
  const int nc = rootsIn(derivative(c, deg), deg - 1, lo, hi, crit);
  double knots[6];
  int nk = 0;
  knots[nk++] = lo;
  for (int i = 0; i < nc; ++i) knots[nk++] = crit[i];
  knots[nk++] = hi;
  int n = 0;
  for (int i = 0; i + 1 < nk; ++i) {
    const double fa = evalDeg(c, deg, knots[i]);
    const double fb = evalDeg(c, deg, knots[i + 1]);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
      out[n++] = bisect(c, deg, knots[i], knots[i + 1]);
    } else if (fb == 0.0 && i + 2 < nk) {
      out[n++] = knots[i + 1];
    }
  }
  return n;
}

/// Whether p is surely positive on [0, t_max]: every Bernstein coefficient of p on the interval
/// (or on each half of it) above a margin far larger than the rounding of any evaluation of p
/// there. The curve lies in the convex hull of its Bernstein coefficients, so when this holds the
/// full search could only find p positive at every knot, and it is skipped (it answers the same:
/// never). Most candidate contacts end here.
bool surelyPositive(const Coeffs& c, double t_max) {
  double a[5];
  double scale = 0.0;
  double tp = 1.0;
  for (size_t i = 0; i < 5; ++i) {
    a[i] = c[i] * tp;
    scale += std::abs(a[i]);
    tp *= t_max;
  }
  const double margin = 1e-12 * scale;
  // Power to Bernstein basis, degree 4: b_k = sum over i <= k of C(k,i)/C(4,i)·a_i.
  double b[5] = {a[0], a[0] + 0.25 * a[1], a[0] + 0.5 * a[1] + a[2] / 6.0,
                 a[0] + 0.75 * a[1] + 0.5 * a[2] + 0.25 * a[3], a[0] + a[1] + a[2] + a[3] + a[4]};
  auto above = [margin](const double* x) {
    for (int k = 0; k < 5; ++k) {
      if (!(x[k] > margin)) return false;
    }
    return true;
  };
  if (above(b)) return true;
  if (!(b[0] > margin) || !(b[4] > margin)) return false;  // p is not clear at an end
  // One de Casteljau split at the middle: left gets l[k], right gets r[k].
  double l[5], r[5];
  double w[5] = {b[0], b[1], b[2], b[3], b[4]};
  for (int level = 0; level < 5; ++level) {
    l[level] = w[0];
    r[4 - level] = w[4 - level];
    for (int k = 0; k + level < 4; ++k) w[k] = 0.5 * (w[k] + w[k + 1]);
  }
  return above(l) && above(r);
}

}  // namespace

double evaluate(const Quartic& p, double t) {
  return evalDeg(p, 4, t);
}

double earliestClosing(const Quartic& p, double t_max) {
  if (!(t_max > 0.0)) return kNever;
  const double f0 = p[0];
  if (f0 <= 0.0 && (p[1] < 0.0 || (p[1] == 0.0 && p[2] < 0.0))) return 0.0;
  if (f0 > 0.0 && surelyPositive(p, t_max)) return kNever;
  // Knots: 0, the critical points, t_max. The first piece whose start is positive and whose
  // end is at or below zero holds the crossing.
  double crit[4];
  const int nc = rootsIn(derivative(p, 4), 3, 0.0, t_max, crit);
  double prev_t = 0.0;
  double prev_f = f0;
  for (int i = 0; i <= nc; ++i) {
    const double t = i < nc ? crit[i] : t_max;
    const double f = evaluate(p, t);
    if (prev_f > 0.0 && f <= 0.0) return bisect(p, 4, prev_t, t);
    // Still closed (a contact that never opened past rounding) at a turn of the gap: from here
    // it closes again, so this is the contact.
    if (prev_f <= 0.0 && f <= 0.0 && i < nc) return t;
    prev_t = t;
    prev_f = f;
  }
  return kNever;
}

}  // namespace pool::physics
