// Watchdog checks: non-finite balls, deep overlaps, balls outside the table, each fixed with an
// event.
#include "physics/watchdog.h"

#include <cmath>

namespace pool::physics {

namespace {

constexpr double kOverlapLimit = 1e-3;   // m: contacts resolve at micrometres; 1 mm is a fault
constexpr double kOutlineMargin = 0.05;  // m beyond the noses before a ball counts as gone

double noseReach(const table::PhysicsParams& p) {
  const double lift = p.cushion_height - p.ball_radius;
  return std::sqrt(std::max(0.0, p.ball_radius * p.ball_radius - lift * lift));
}

}  // namespace

bool freeSpotOnLongString(const std::vector<Ball>& balls, size_t self, const TableFeatures& f,
                          const table::PhysicsParams& p, Vec2& spot) {
  const double R = p.ball_radius;
  const double foot_x = f.half_length / 2.0;
  const double step = R / 4.0;
  for (int dir : {1, -1}) {
    for (double x = foot_x; std::abs(x) <= f.half_length - R; x += dir * step) {
      const Vec2 c(x, 0.0);
      bool free = true;
      for (size_t k = 0; k < balls.size() && free; ++k) {
        if (k == self || !onTable(balls[k].state)) continue;
        free = (balls[k].pos.head<2>() - c).norm() >= 2.0 * R;
      }
      if (free) {
        spot = c;
        return true;
      }
    }
  }
  return false;
}

bool onSlate(const Vec2& p, const TableFeatures& f, const table::PhysicsParams& params) {
  const double dh = noseReach(params);
  const double eps = 1e-9;
  // Within the cushions' outline: the noses and jaw points below say where the cushions are;
  // this only keeps out points beyond every cushion. A ball may rest in a pocket's mouth, past
  // the line of the rails, as long as it is not over the hole.
  if (std::abs(p.x()) > f.half_length + kOutlineMargin ||
      std::abs(p.y()) > f.half_width + kOutlineMargin) {
    return false;
  }
  for (const auto& h : f.holes) {
    if ((p - h.c).norm() < h.radius) return false;
  }
  for (const auto& n : f.noses) {
    const double q = (p - n.a).dot(n.dir);
    if (q >= 0.0 && q <= n.length && (p - n.a).dot(n.normal) < dh - eps) return false;
  }
  for (const auto& pt : f.points) {
    if ((p - pt.c).norm() < dh - eps) return false;
  }
  return true;
}

std::vector<WatchdogFix> checkBalls(const std::vector<Ball>& balls, const TableFeatures& f,
                                    const table::PhysicsParams& p) {
  std::vector<WatchdogFix> fixes;
  auto fix = [&](size_t i, const char* reason) {
    WatchdogFix w;
    w.index = i;
    w.reason = reason;
    w.remove = !freeSpotOnLongString(balls, i, f, p, w.spot);
    fixes.push_back(w);
  };
  for (size_t i = 0; i < balls.size(); ++i) {
    const Ball& b = balls[i];
    if (!onTable(b.state)) continue;
    if (!b.pos.allFinite() || !b.vel.allFinite() || !b.ang_vel.allFinite() ||
        !b.orient.coeffs().allFinite()) {
      fix(i, "non-finite state");
      continue;
    }
    if (b.state != MotionState::Airborne &&
        (std::abs(b.pos.x()) > f.half_length + kOutlineMargin ||
         std::abs(b.pos.y()) > f.half_width + kOutlineMargin || b.pos.z() < 0.0)) {
      fix(i, "left the slate");
      continue;
    }
    const double overlap = 2.0 * p.ball_radius - kOverlapLimit;
    for (size_t k = i + 1; k < balls.size(); ++k) {
      if (!onTable(balls[k].state)) continue;
      const Vec3 d = balls[k].pos - b.pos;
      // Most pairs are apart along x or y alone; the distance only for the rest.
      if (std::abs(d.x()) >= overlap || std::abs(d.y()) >= overlap) continue;
      if (d.norm() < overlap) {
        fix(k, "inside another ball");
        break;
      }
    }
  }
  return fixes;
}

}  // namespace pool::physics
