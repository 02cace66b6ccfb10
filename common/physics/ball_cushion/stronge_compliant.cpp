// Stronge's compliant frictional impact of a ball on a cushion, as pooltool uses it by default:
// normal and tangential springs through the contact, Coulomb friction, energy restitution.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/ball_cushion/cushion_model.h"

namespace pool::physics {
namespace {

// Sphere on a half-space: a normal impulse P changes the contact's normal velocity by P/m
// (beta_n = 1), a tangential one its tangential velocity by (1 + mR²/I)·P/m = 3.5·P/m.
constexpr double kBetaN = 1.0;
constexpr double kBetaT = 3.5;
// Time steps through the compression (the restitution takes as many per unit of time).
constexpr int kSteps = 400;

/// The contact in its own axes during the impact (time in units of 1/ω_n, mass 1, k_n = 1).
struct Contact {
  double un, ut;       ///< normal (< 0 approaching) and tangential relative velocity
  double delta = 0.0;  ///< normal spring's compression
  double xi = 0.0;     ///< tangential spring's stretch
  double pn = 0.0;     ///< normal impulse so far (per unit mass)
  double pt = 0.0;     ///< tangential impulse so far
};

class CushionStrongeCompliant final : public CushionModel {
 public:
  CushionStrongeCompliant(const table::PhysicsParams& p, double frequency_ratio)
      : R_(p.ball_radius), m_(p.ball_mass), mu_(p.u_c), ratio_(frequency_ratio) {}

  double resolve(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                 bool on_slate) const override {
    // As pooltool 0.6 does: the contact at the nose, along the 3-D normal from the nose line to
    // the ball's centre. A sphere's response is the same in every tangential direction, so the
    // slip keeps its initial direction and the impact is one-dimensional along it.
    const Vec3& n = normal;
    const Vec3 r = -R_ * n;
    const Vec3 u = vel + ang_vel.cross(r);
    const double un = u.dot(n);
    if (un >= 0.0) return 0.0;
    const Vec3 slip = u - un * n;
    const double ut = slip.norm();
    const Vec3 t = ut > 0.0 ? Vec3(slip / ut) : Vec3::Zero();
    const Contact c = impact({un, ut}, restitution);
    const Vec3 impulse = m_ * (c.pn * n + c.pt * t);
    vel += impulse / m_;
    ang_vel += r.cross(impulse) / (0.4 * m_ * R_ * R_);
    // On the slate, the slate takes the vertical part (pooltool's planar model drops it too).
    if (on_slate) vel.z() = 0.0;
    return -un;
  }

 private:
  /// Integrates the springs through compression and restitution (Stronge: unloading stiffness
  /// k_n/e², so restitution returns e² of the stored energy); the tangential spring sticks until
  /// its force reaches μ times the normal force, then slips.
  Contact impact(Contact c, double e) const {
    const double kt = ratio_ * ratio_ / kBetaT;  // k_t / k_n (per β_t)
    const double dt = 0.5 * std::numbers::pi / kSteps;
    bool compressing = true;
    double delta_max = 0.0;
    for (int k = 0; k < 8 * kSteps; ++k) {
      double fn = compressing ? c.delta : (c.delta - delta_max * (1.0 - e * e)) / (e * e);
      if (!compressing && fn <= 0.0) break;
      double ft = -kt * c.xi;
      if (std::abs(ft) > mu_ * fn) {  // slipping: the spring stays at the friction limit
        ft = std::copysign(mu_ * fn, ft);
        c.xi = -ft / kt;
      }
      c.un += kBetaN * fn * dt;
      c.ut += kBetaT * ft * dt;
      c.pn += fn * dt;
      c.pt += ft * dt;
      c.delta -= c.un * dt;
      c.xi += c.ut * dt;
      if (compressing && c.un >= 0.0) {
        compressing = false;
        delta_max = c.delta;
        if (e <= 0.0) break;
      }
    }
    return c;
  }

  double R_, m_, mu_, ratio_;
};

}  // namespace

std::unique_ptr<CushionModel> makeCushionStrongeCompliant(const table::PhysicsParams& params,
                                                          double frequency_ratio) {
  return std::make_unique<CushionStrongeCompliant>(params, frequency_ratio);
}

}  // namespace pool::physics
