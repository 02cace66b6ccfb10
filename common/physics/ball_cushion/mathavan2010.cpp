// Mathavan, Jackson & Parkin (2010)'s cushion model: nose and slate contacts at once, with friction
// at both, integrated over the nose's normal impulse; restitution by energy.
#include <algorithm>
#include <cmath>

#include "physics/ball_cushion/cushion_model.h"

namespace pool::physics {
namespace {

/// The ball during the impact: velocity and spin, both changing with the normal impulse.
struct State {
  Vec3 v, w;
};

class CushionMathavan2010 final : public CushionModel {
 public:
  CushionMathavan2010(const table::PhysicsParams& p, int steps)
      : steps_(steps),
        R_(p.ball_radius),
        m_(p.ball_mass),
        inv_m_(1.0 / p.ball_mass),
        inv_inertia_(1.0 / (0.4 * p.ball_mass * p.ball_radius * p.ball_radius)),
        mu_nose_(p.u_c),
        mu_slate_(p.u_s) {}

  double resolve(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                 bool on_slate) const override {
    const double approach = -vel.dot(normal);
    if (approach <= 0.0) return 0.0;
    // The steps are first order in the impulse step: two runs, N and 2N steps, extrapolated
    // (Richardson) cancel that error.
    const State coarse = integrate({vel, ang_vel}, normal, restitution, on_slate, steps_);
    const State fine = integrate({vel, ang_vel}, normal, restitution, on_slate, 2 * steps_);
    vel = 2.0 * fine.v - coarse.v;
    ang_vel = 2.0 * fine.w - coarse.w;
    return approach;
  }

 private:
  /// Compression, then restitution until the normal impulse gives back e² of the compression's
  /// work; `steps` impulse steps in the compression.
  State integrate(State s, const Vec3& n, double e, bool on_slate, int steps) const {
    const double step = m_ * -s.v.dot(n) / steps;
    const double work = compress(s, n, on_slate, step, steps);
    restitute(s, n, on_slate, step, steps, e * e * work);
    return s;
  }

  // Inlined by force (the impulse loop's cost is in these calls); the arithmetic is unchanged.
  [[gnu::always_inline]] void apply(State& s, const Vec3& impulse, const Vec3& at) const {
    s.v += inv_m_ * impulse;
    s.w += inv_inertia_ * at.cross(impulse);
  }

  /// The friction impulse against `slip` (m/s) at a contact: what stops the slip if at most
  /// `limit` (N·s), otherwise `limit` against it. A tangential impulse P changes a sphere's
  /// contact point velocity by (1/m + R²/I)·P = 7P/(2m).
  [[gnu::always_inline]] Vec3 friction(const Vec3& slip, double limit) const {
    const double speed = slip.norm();
    const double stop = 2.0 * m_ / 7.0 * speed;
    if (stop <= limit) return -2.0 * m_ / 7.0 * slip;
    return -limit / speed * slip;
  }

  /// One step of normal impulse dp at the nose, with its friction, the slate's reaction (what
  /// keeps the ball on the slate) and the slate's friction. Each friction sees the slip the
  /// impulses before it leave, so a slip that reaches zero stays there (a stick) instead of
  /// reversing from step to step.
  [[gnu::always_inline]] void impulseStep(State& s, const Vec3& n, bool on_slate, double dp) const {
    const Vec3 r_nose = -R_ * n;
    const Vec3 normal_impulse = dp * n;
    apply(s, normal_impulse, r_nose);
    const Vec3 u_nose = s.v + s.w.cross(r_nose);
    const Vec3 f_nose = friction(u_nose - u_nose.dot(n) * n, mu_nose_ * dp);
    apply(s, f_nose, r_nose);
    const double lift = (normal_impulse + f_nose).z();
    if (!on_slate || lift >= 0.0) return;
    const Vec3 r_slate(0.0, 0.0, -R_);
    apply(s, Vec3(0.0, 0.0, -lift), r_slate);
    const Vec3 u_slate = s.v + s.w.cross(r_slate);
    apply(s, friction(Vec3(u_slate.x(), u_slate.y(), 0.0), -mu_slate_ * lift), r_slate);
  }

  /// Until the contact stops approaching; returns the work of the normal impulse (J, > 0).
  double compress(State& s, const Vec3& n, bool on_slate, double step, int steps) const {
    double work = 0.0;
    for (int k = 0; k < 16 * steps; ++k) {
      const double un = s.v.dot(n);  // < 0 while approaching
      if (un >= 0.0) break;
      State next = s;
      impulseStep(next, n, on_slate, step);
      double dp = step;
      double un_next = next.v.dot(n);
      const bool ends = un_next >= 0.0;
      // The approach ends within this step: find where (secant steps on un, nearly linear in P).
      for (int i = 0; ends && i < 3 && un_next != 0.0; ++i) {
        dp *= -un / (un_next - un);
        next = s;
        impulseStep(next, n, on_slate, dp);
        un_next = next.v.dot(n);
      }
      work += -0.5 * (un + un_next) * dp;
      s = next;
      if (ends) break;
    }
    return work;
  }

  /// Until the normal impulse has given back `target` of work (J).
  void restitute(State& s, const Vec3& n, bool on_slate, double step, int steps,
                 double target) const {
    double work = 0.0;
    for (int k = 0; k < 16 * steps && work < target; ++k) {
      const double un = std::max(0.0, s.v.dot(n));
      State next = s;
      impulseStep(next, n, on_slate, step);
      const double slope = (next.v.dot(n) - un) / step;  // d(un)/dP
      const double full = (un + 0.5 * slope * step) * step;
      double dp = step;
      if (work + full >= target) {
        // un·dp + slope·dp²/2 = left, the root nearest zero
        const double left = target - work;
        const double disc = std::max(0.0, un * un + 2.0 * slope * left);
        const double denominator = un + std::sqrt(disc);
        if (denominator > 0.0) dp = std::min(step, 2.0 * left / denominator);
        next = s;
        impulseStep(next, n, on_slate, dp);
      }
      work += (un + 0.5 * slope * dp) * dp;
      s = next;
      if (dp < step) break;
    }
  }

  int steps_;
  double R_, m_, inv_m_, inv_inertia_, mu_nose_, mu_slate_;
};

}  // namespace

std::unique_ptr<CushionModel> makeCushionMathavan2010(const table::PhysicsParams& params,
                                                      int steps) {
  return std::make_unique<CushionMathavan2010>(params, std::max(1, steps));
}

}  // namespace pool::physics
