// Frictional, inelastic impulse between two equal balls (Alciatore), and its ball–ball model.
#include "physics/ball_ball/alciatore.h"

#include <cmath>

#include "physics/ball_ball/ball_ball_model.h"

namespace pool::physics {

double alciatoreFriction(double sliding_speed) {
  return 0.00995 + 0.108 * std::exp(-1.088 * sliding_speed);
}

double resolveBallBall(const Vec3& pa, Vec3& va, Vec3& wa, const Vec3& pb, Vec3& vb, Vec3& wb,
                       double restitution, std::optional<double> friction, double radius,
                       double mass) {
  const Vec3 n = (pb - pa).normalized();  // a → b
  // Velocities of the two contact points (a's at +R n, b's at −R n).
  const Vec3 ua = va + wa.cross(radius * n);
  const Vec3 ub = vb + wb.cross(-radius * n);
  const Vec3 u = ua - ub;
  const double un = u.dot(n);
  if (un <= 0.0) return 0.0;

  // Normal impulse on b (a gets the opposite): equal masses share (1 + e)·un.
  const double pn = 0.5 * (1.0 + restitution) * mass * un;

  // Tangential: an impulse P on b (−P on a) changes the relative slip by −(7/m)·P.
  const Vec3 slip = u - un * n;
  const double slip_speed = slip.norm();
  Vec3 pt = Vec3::Zero();
  if (slip_speed > 0.0) {
    const double mu = friction ? *friction : alciatoreFriction(slip_speed);
    const double stick = mass / 7.0 * slip_speed;
    pt = std::min(stick, mu * pn) / slip_speed * slip;
  }
  const Vec3 p = pn * n + pt;  // on b
  const double inertia = 0.4 * mass * radius * radius;
  va -= p / mass;
  vb += p / mass;
  // a receives −p at +R n, b receives +p at −R n: the same change of spin for both.
  const Vec3 dw = (radius * n).cross(-p) / inertia;
  wa += dw;
  wb += dw;
  return un;
}

}  // namespace pool::physics

namespace pool::physics {
namespace {

class BallBallAlciatore final : public BallBallModel {
 public:
  explicit BallBallAlciatore(const table::PhysicsParams& p) : p_(p) {}
  double resolve(const Vec3& pa, Vec3& va, Vec3& wa, const Vec3& pb, Vec3& vb, Vec3& wb,
                 double restitution) const override {
    return resolveBallBall(pa, va, wa, pb, vb, wb, restitution, p_.u_b, p_.ball_radius,
                           p_.ball_mass);
  }

 private:
  table::PhysicsParams p_;
};

}  // namespace

std::unique_ptr<BallBallModel> makeBallBallAlciatore(const table::PhysicsParams& params) {
  return std::make_unique<BallBallAlciatore>(params);
}

}  // namespace pool::physics
