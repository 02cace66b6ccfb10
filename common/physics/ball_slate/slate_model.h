// Ball–slate contact models behind one interface: a ball landing on, or driven into, the slate.
#pragma once

#include <memory>

#include "physics/ball.h"
#include "table/physics_params.h"

namespace pool::physics {

/// The interface every ball–slate model implements.
class SlateModel {
 public:
  virtual ~SlateModel() = default;
  /// Bounces a ball moving down into the slate, changing its velocity (m/s) and spin (rad/s),
  /// with the spec's slate restitution and the cloth friction `friction` (0 while the cue tip
  /// pins the ball). Returns the approach speed (m/s), or 0 if it was not moving down.
  virtual double bounce(Vec3& vel, Vec3& ang_vel, double friction) const = 0;
};

/// The rigid impulse with Coulomb friction of rigid_coulomb.h, against the slate's normal.
std::unique_ptr<SlateModel> makeSlateRigidCoulomb(const table::PhysicsParams& params);

}  // namespace pool::physics
