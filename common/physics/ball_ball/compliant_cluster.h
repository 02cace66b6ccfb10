// Balls that touch when one of them is struck (a rack at the break): every contact resolved
// together through Hertzian springs, independent of the balls' order.
#pragma once

#include <cstddef>
#include <vector>

#include "physics/ball.h"

namespace pool::physics {

/// A pair of balls (indices into the cluster) that pressed on each other during the impact.
struct ClusterContact {
  std::size_t a = 0, b = 0;
  double speed = 0.0;  ///< the largest approach speed along their line of centres, m/s
};

/// Resolves the impact of balls whose centres are at `pos` (m, fixed during the impact: it lasts
/// well under a millisecond) and whose velocities `vel` (m/s) are changed. Every pair whose gap is
/// at most `touch_gap` (m) is a contact: a Hertzian spring F = k·δ^(3/2) on compression, and on
/// unloading F = F_max·((δ − δ_r)/(δ_max − δ_r))^(3/2) with δ_r = (1 − e²)·δ_max, which returns
/// e² of the stored energy. The impact is integrated in time until no contact pushes and none
/// approaches. Forces act along the lines of centres (spins are unchanged); momentum is conserved
/// pair by pair, energy never rises, and the result does not depend on the balls' order.
/// Returns the pairs that touched, a < b.
std::vector<ClusterContact> resolveCompliantCluster(const std::vector<Vec3>& pos,
                                                    std::vector<Vec3>& vel, double restitution,
                                                    double radius, double mass, double touch_gap);

}  // namespace pool::physics
