// Ball–ball contact models behind one interface: the impulse of two equal balls colliding.
#pragma once

#include <memory>

#include "physics/ball.h"
#include "table/physics_params.h"

namespace pool::physics {

/// The interface every ball–ball model implements.
class BallBallModel {
 public:
  virtual ~BallBallModel() = default;
  /// Resolves a collision of balls a and b touching at centres pa, pb (m), changing their
  /// velocities (m/s) and spins (rad/s). `restitution` is the normal restitution to use (the
  /// event loop passes 0 for a push). Returns the approach speed along the line of centres
  /// (m/s), or 0 if they were not approaching (then nothing changes).
  virtual double resolve(const Vec3& pa, Vec3& va, Vec3& wa, const Vec3& pb, Vec3& vb, Vec3& wb,
                         double restitution) const = 0;
};

/// Alciatore's frictional impulse (TP A-14 friction unless params.u_b sets a constant).
std::unique_ptr<BallBallModel> makeBallBallAlciatore(const table::PhysicsParams& params);

}  // namespace pool::physics
