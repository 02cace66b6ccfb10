// Impulse of a ball on a fixed contact, with restitution and Coulomb friction; the slate model.
#include "physics/ball_slate/rigid_coulomb.h"

#include "physics/ball_slate/slate_model.h"

namespace pool::physics {

double resolveFixedContact(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                           double friction, double radius, double mass) {
  const Vec3 r = -radius * normal;  // centre → contact point
  const Vec3 u = vel + ang_vel.cross(r);
  const double un = u.dot(normal);
  if (un >= 0.0) return 0.0;

  // Normal impulse: the approach speed comes back scaled by the restitution.
  const double pn = -(1.0 + restitution) * mass * un;

  // Tangential: for a solid sphere a tangential impulse P changes the contact point's velocity
  // by (7 / 2m) P, so stopping the slip takes (2m/7)·|slip|.
  const Vec3 slip = u - un * normal;
  const double slip_speed = slip.norm();
  Vec3 pt = Vec3::Zero();
  if (slip_speed > 0.0) {
    const double stick = 2.0 * mass / 7.0 * slip_speed;
    pt = -std::min(stick, friction * pn) / slip_speed * slip;
  }
  const Vec3 p = pn * normal + pt;
  const double inertia = 0.4 * mass * radius * radius;
  vel += p / mass;
  ang_vel += r.cross(p) / inertia;
  return -un;
}

}  // namespace pool::physics

namespace pool::physics {
namespace {

class SlateRigidCoulomb final : public SlateModel {
 public:
  explicit SlateRigidCoulomb(const table::PhysicsParams& p) : p_(p) {}
  double bounce(Vec3& vel, Vec3& ang_vel, double friction) const override {
    return resolveFixedContact(vel, ang_vel, Vec3::UnitZ(), p_.e_slate, friction, p_.ball_radius,
                               p_.ball_mass);
  }

 private:
  table::PhysicsParams p_;
};

}  // namespace

std::unique_ptr<SlateModel> makeSlateRigidCoulomb(const table::PhysicsParams& params) {
  return std::make_unique<SlateRigidCoulomb>(params);
}

}  // namespace pool::physics
