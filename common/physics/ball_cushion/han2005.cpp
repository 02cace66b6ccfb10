// Han (2005)'s cushion model: one rigid impulse at the nose, with restitution and Coulomb friction.
#include "physics/ball_cushion/cushion_model.h"
#include "physics/ball_slate/rigid_coulomb.h"

namespace pool::physics {
namespace {

class CushionHan2005 final : public CushionModel {
 public:
  explicit CushionHan2005(const table::PhysicsParams& p) : p_(p) {}
  double resolve(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                 bool /*on_slate*/) const override {
    return resolveFixedContact(vel, ang_vel, normal, restitution, p_.u_c, p_.ball_radius,
                               p_.ball_mass);
  }

 private:
  table::PhysicsParams p_;
};

}  // namespace

std::unique_ptr<CushionModel> makeCushionHan2005(const table::PhysicsParams& params) {
  return std::make_unique<CushionHan2005>(params);
}

}  // namespace pool::physics
