// Mathavan, Jackson & Parkin (2010)'s cushion model: nose and slate contacts at once, with friction
// at both, integrated over the nose's normal impulse; restitution by energy.
#include <algorithm>
#include <cmath>

#include "physics/ball_cushion/cushion_model.h"

namespace pool::physics {
namespace {

// A slip slower than this (relative to the approach speed) has no direction: no friction.
constexpr double kSlipEps = 1e-12;

/// The ball during the impact: velocity and spin, both changing with the normal impulse.
struct State {
  Vec3 v, w;
};

Vec3 direction(const Vec3& slip, double scale) {
  const double s = slip.norm();
  return s > kSlipEps * scale ? Vec3(slip / s) : Vec3::Zero();
}

class CushionMathavan2010 final : public CushionModel {
 public:
  CushionMathavan2010(const table::PhysicsParams& p, int steps)
      : steps_(steps),
        R_(p.ball_radius),
        m_(p.ball_mass),
        inertia_(0.4 * p.ball_mass * p.ball_radius * p.ball_radius),
        mu_nose_(p.u_c),
        mu_slate_(p.u_s) {}

  double resolve(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                 bool on_slate) const override {
    const double approach = -vel.dot(normal);
    if (approach <= 0.0) return 0.0;
    State s{vel, ang_vel};
    const double step = m_ * approach / steps_;
    const double work = compress(s, normal, on_slate, step, approach);
    restitute(s, normal, on_slate, step, approach, restitution * restitution * work);
    vel = s.v;
    ang_vel = s.w;
    return approach;
  }

 private:
  /// dv/dP and dω/dP: the nose's unit normal impulse with its friction against the nose slip,
  /// and the slate's reaction (whatever keeps the ball on the slate) with its friction.
  State rates(const State& s, const Vec3& n, bool on_slate, double scale) const {
    const Vec3 r_nose = -R_ * n;
    const Vec3 u_nose = s.v + s.w.cross(r_nose);
    const Vec3 f_nose = n - mu_nose_ * direction(u_nose - u_nose.dot(n) * n, scale);
    Vec3 f_slate = Vec3::Zero();
    const Vec3 r_slate(0.0, 0.0, -R_);
    if (on_slate && f_nose.z() < 0.0) {
      const Vec3 u_slate = s.v + s.w.cross(r_slate);
      const Vec3 slip(u_slate.x(), u_slate.y(), 0.0);
      f_slate = -f_nose.z() * (Vec3::UnitZ() - mu_slate_ * direction(slip, scale));
    }
    return {(f_nose + f_slate) / m_, (r_nose.cross(f_nose) + r_slate.cross(f_slate)) / inertia_};
  }

  static void advance(State& s, const State& rate, double dp) {
    s.v += dp * rate.v;
    s.w += dp * rate.w;
  }

  /// Until the contact stops approaching; returns the work of the normal impulse (J, > 0).
  double compress(State& s, const Vec3& n, bool on_slate, double step, double scale) const {
    double work = 0.0;
    for (int k = 0; k < 16 * steps_; ++k) {
      const double un = s.v.dot(n);  // < 0 while approaching
      if (un >= 0.0) break;
      const State rate = rates(s, n, on_slate, scale);
      const double dun = rate.v.dot(n);  // d(un)/dP
      const double dp = (dun > 0.0 && un + dun * step > 0.0) ? -un / dun : step;
      advance(s, rate, dp);
      work += -(un + 0.5 * dun * dp) * dp;  // un is linear in P over the step
      if (dp < step) break;
    }
    return work;
  }

  /// Until the normal impulse has given back `target` of work (J).
  void restitute(State& s, const Vec3& n, bool on_slate, double step, double scale,
                 double target) const {
    double work = 0.0;
    for (int k = 0; k < 16 * steps_ && work < target; ++k) {
      const double un = std::max(0.0, s.v.dot(n));
      const State rate = rates(s, n, on_slate, scale);
      const double dun = rate.v.dot(n);
      double dp = step;
      const double full = (un + 0.5 * dun * step) * step;
      if (work + full >= target) {
        // un·dp + dun·dp²/2 = left, the root nearest zero
        const double left = target - work;
        const double disc = std::max(0.0, un * un + 2.0 * dun * left);
        const double denominator = un + std::sqrt(disc);
        if (denominator > 0.0) dp = std::min(step, 2.0 * left / denominator);
      }
      advance(s, rate, dp);
      work += (un + 0.5 * dun * dp) * dp;
      if (dp < step) break;
    }
  }

  int steps_;
  double R_, m_, inertia_, mu_nose_, mu_slate_;
};

}  // namespace

std::unique_ptr<CushionModel> makeCushionMathavan2010(const table::PhysicsParams& params,
                                                      int steps) {
  return std::make_unique<CushionMathavan2010>(params, std::max(1, steps));
}

}  // namespace pool::physics
