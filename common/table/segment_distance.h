// The distance in the table plane from a point to a segment: how near a ball's path passes a ball.
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace pool::table {

/// The distance from `p` to the segment from `a` to `b` (to `a` when the segment is a point).
inline double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace pool::table
