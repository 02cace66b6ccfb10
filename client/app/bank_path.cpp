// The cue ball's line mirrored off the cushions, to a ball or its last cushion.
#include "client/app/bank_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "client/app/aim_line.h"

namespace pool::app {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

BankPath bankPath(const Eigen::Vector2d& cue, double yaw, const std::vector<physics::Ball>& balls,
                  const game::LoadedTable& view, int struck, int cushions, double tail) {
  const double r = view.radius();
  const double hx = view.halfLength() - r, hy = view.halfWidth() - r;
  BankPath path;
  path.points.push_back(cue);
  Eigen::Vector2d at = cue;
  Eigen::Vector2d dir(std::cos(yaw), std::sin(yaw));
  // Each leg: to the nearest ball or cushion ahead; a leg after the last cushion ends at `tail`.
  for (int leg = 0; leg <= cushions; ++leg) {
    double to_x = kInf, to_y = kInf;
    if (dir.x() > 1e-12) to_x = (hx - at.x()) / dir.x();
    if (dir.x() < -1e-12) to_x = (-hx - at.x()) / dir.x();
    if (dir.y() > 1e-12) to_y = (hy - at.y()) / dir.y();
    if (dir.y() < -1e-12) to_y = (-hy - at.y()) / dir.y();
    const double wall = std::max(0.0, std::min(to_x, to_y));
    const double reach = leg == cushions ? std::min(wall, tail) : wall;
    double nearest = reach;
    std::optional<int> met;
    for (const auto& b : balls) {
      if (b.id == struck || !physics::onTable(b.state)) continue;
      // From a cushion the ball leaves where it touched: a ball it already touches is not met.
      const double t = sweep(at, dir, b.pos.head<2>(), 2 * r);
      if (t > 1e-9 && t < nearest) {
        nearest = t;
        met = b.id;
      }
    }
    at += nearest * dir;
    path.points.push_back(at);
    if (met) {
      path.ball = met;
      return path;
    }
    if (leg == cushions) break;
    ++path.cushions;
    // Mirrored in the cushion met (both in a corner).
    if (std::abs(to_x - wall) < 1e-12) dir.x() = -dir.x();
    if (std::abs(to_y - wall) < 1e-12) dir.y() = -dir.y();
  }
  return path;
}

}  // namespace pool::app
