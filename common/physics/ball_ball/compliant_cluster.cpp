// Simultaneous Hertzian contacts of touching balls, integrated through the impact.
#include "physics/ball_ball/compliant_cluster.h"

#include <algorithm>
#include <cmath>

namespace pool::physics {
namespace {

// Hertz stiffness of two phenolic resin balls (E ≈ 5 GPa, ν ≈ 0.35): k = (4/3)·E*·√(R/2), with
// E* = E / (2(1 − ν²)). For a power-law spring the outcome does not depend on k (it scales time
// only); k sets the contact time, a few hundred microseconds at break speeds.
constexpr double kYoung = 5e9;  // Pa
constexpr double kPoisson = 0.35;
// Time steps per contact time of the fastest approach.
constexpr double kStepsPerContact = 50.0;
// A guard against a contact network that never comes apart (never reached by real shots).
constexpr int kMaxSteps = 2000000;

struct Spring {
  std::size_t a, b;
  Vec3 n;        ///< unit, a → b
  double delta;  ///< compression, m (negative: a gap)
  double delta_max = 0.0;
  double force_max = 0.0;
  double speed = 0.0;  ///< largest approach speed seen
  bool touched = false;
};

double hertzStiffness(double radius) {
  const double e_star = kYoung / (2.0 * (1.0 - kPoisson * kPoisson));
  return 4.0 / 3.0 * e_star * std::sqrt(0.5 * radius);
}

/// The spring's force (N, ≥ 0) at its current compression, updating its loading history.
double springForce(Spring& s, double k, double e) {
  if (s.delta <= 0.0) return 0.0;
  if (s.delta >= s.delta_max) {
    s.delta_max = s.delta;
    s.force_max = k * s.delta * std::sqrt(s.delta);
    return s.force_max;
  }
  const double rest = (1.0 - e * e) * s.delta_max;
  if (s.delta <= rest) return 0.0;
  const double x = (s.delta - rest) / (s.delta_max - rest);
  return s.force_max * x * std::sqrt(x);
}

std::vector<Spring> findSprings(const std::vector<Vec3>& pos, const std::vector<Vec3>& vel,
                                double radius, double touch_gap) {
  std::vector<Spring> springs;
  for (std::size_t a = 0; a < pos.size(); ++a) {
    for (std::size_t b = a + 1; b < pos.size(); ++b) {
      const Vec3 d = pos[b] - pos[a];
      const double gap = d.norm() - 2.0 * radius;
      if (gap > touch_gap) continue;
      Spring s{a, b, d.normalized(), -gap};
      s.speed = std::max(0.0, (vel[a] - vel[b]).dot(s.n));
      springs.push_back(s);
    }
  }
  return springs;
}

/// Time step: a fraction of the Hertzian contact time 2.87·(m_eff²/(R_eff·E*²·v))^(1/5) at the
/// fastest approach.
double timeStep(const std::vector<Spring>& springs, double k, double mass) {
  double v = 0.0;
  for (const Spring& s : springs) v = std::max(v, s.speed);
  v = std::max(v, 1e-3);
  const double m_eff = 0.5 * mass;
  const double contact = 3.21 * std::pow(m_eff / k, 0.4) * std::pow(v, -0.2);
  return contact / kStepsPerContact;
}

}  // namespace

std::vector<ClusterContact> resolveCompliantCluster(const std::vector<Vec3>& pos,
                                                    std::vector<Vec3>& vel, double restitution,
                                                    double radius, double mass, double touch_gap) {
  std::vector<Spring> springs = findSprings(pos, vel, radius, touch_gap);
  const double k = hertzStiffness(radius);
  const double dt = timeStep(springs, k, mass);
  for (int step = 0; step < kMaxSteps; ++step) {
    bool active = false;
    for (Spring& s : springs) {
      const double f = springForce(s, k, restitution);
      if (f <= 0.0) continue;
      s.touched = true;
      active = true;
      const Vec3 dv = (f * dt / mass) * s.n;
      vel[s.a] -= dv;
      vel[s.b] += dv;
    }
    for (Spring& s : springs) {
      const double approach = (vel[s.a] - vel[s.b]).dot(s.n);
      s.delta += approach * dt;
      s.speed = std::max(s.speed, approach);
      active = active || (approach > 0.0 && s.delta > 0.0);
    }
    if (!active) break;
  }
  std::vector<ClusterContact> out;
  for (const Spring& s : springs) {
    if (s.touched) out.push_back({s.a, s.b, s.speed});
  }
  return out;
}

}  // namespace pool::physics
