// Ball–cushion contact models behind one interface: a ball striking a cushion nose or a jaw point.
#pragma once

#include <memory>

#include "physics/ball.h"
#include "table/physics_params.h"

namespace pool::physics {

/// The interface every ball–cushion model implements.
class CushionModel {
 public:
  virtual ~CushionModel() = default;
  /// Resolves a ball striking a cushion, changing its velocity (m/s) and spin (rad/s).
  /// `normal` is the unit vector from the contact point to the ball's centre (it points down
  /// when the nose is above the centre); `restitution` is the one to use (the event loop passes 0
  /// for a push); `on_slate` says the slate carries the ball during the impact. Returns the
  /// approach speed along the normal (m/s), or 0 if the ball was not approaching (then nothing
  /// changes).
  virtual double resolve(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                         bool on_slate) const = 0;
};

/// Han (2005): one rigid impulse at the nose with Coulomb friction u_c (the slate takes no part).
std::unique_ptr<CushionModel> makeCushionHan2005(const table::PhysicsParams& params);

/// Default impulse steps of the Mathavan model's compression phase (see the convergence test).
constexpr int kMathavanSteps = 16;

/// Mathavan, Jackson & Parkin (2010): the ball touches the nose and the slate during the impact,
/// with friction u_c at the nose and u_s at the slate, integrated over the normal impulse;
/// restitution by energy (the rebound gives back e² of the compression's work). `steps`: impulse
/// steps in the compression phase of the coarser of the two extrapolated runs (the restitution
/// phase takes steps of the same size); the equations are homogeneous in the velocities, so the
/// step is a fixed fraction of the impulse that stops the approach and the cost does not grow
/// with the speed.
std::unique_ptr<CushionModel> makeCushionMathavan2010(const table::PhysicsParams& params,
                                                      int steps = kMathavanSteps);

/// pooltool 0.6's default ratio of the tangential to the normal vibration frequency of the
/// contact in Stronge's model (its resolver's setting; the model needs it in (1, 2)).
constexpr double kStrongeFrequencyRatio = 1.8;

/// Stronge's compliant impact (pooltool 0.6's default cushion model): normal and tangential
/// springs at the contact (`frequency_ratio` ω_t/ω_n), Coulomb friction u_c, unloading stiffness
/// k/e² so the rebound returns e² of the stored energy. As in pooltool 0.6, the contact is at the
/// nose, along the 3-D normal, and a ball on the slate keeps no vertical speed, so the two
/// engines compare like for like.
std::unique_ptr<CushionModel> makeCushionStrongeCompliant(
    const table::PhysicsParams& params, double frequency_ratio = kStrongeFrequencyRatio);

}  // namespace pool::physics
