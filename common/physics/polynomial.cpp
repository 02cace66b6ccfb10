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

}  // namespace

double evaluate(const Quartic& p, double t) {
  return evalDeg(p, 4, t);
}

double earliestClosing(const Quartic& p, double t_max) {
  if (!(t_max > 0.0)) return kNever;
  const double f0 = p[0];
  if (f0 <= 0.0 && (p[1] < 0.0 || (p[1] == 0.0 && p[2] < 0.0))) return 0.0;
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
