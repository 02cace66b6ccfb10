// Real roots of low-degree polynomials on an interval: the time-of-impact solver's core.
#pragma once

#include <array>
#include <limits>

namespace pool::physics {

/// Coefficients c[0] + c[1] t + c[2] t² + c[3] t³ + c[4] t⁴.
using Quartic = std::array<double, 5>;

constexpr double kNever = std::numeric_limits<double>::infinity();

double evaluate(const Quartic& p, double t);

/// The earliest t in [0, t_max] where p goes from positive to zero or below (a gap closing).
/// If p(0) <= 0 it counts as closing at 0 only when p is decreasing there; a gap that is
/// already closed but opening (a contact just resolved) is skipped until it closes again, or
/// until it turns back to closing without ever having opened past zero.
/// kNever if there is none. Exact to a few ulps of t (bisection on monotonic pieces).
double earliestClosing(const Quartic& p, double t_max);

}  // namespace pool::physics
