// Ball–cloth models behind one interface: the constant accelerations of a ball until its next state
// change.
#pragma once

#include <memory>

#include "physics/ball.h"
#include "table/physics_params.h"

namespace pool::physics {

/// What ends a piece of motion.
enum class Transition : std::uint8_t {
  None,         ///< nothing: the ball stays as it is (at rest, or pocketed)
  SlideToRoll,  ///< the contact point stops slipping
  RollToRest,   ///< a rolling ball stops
  SpinEnds,     ///< spin about the vertical reaches zero
  Landing,      ///< an airborne ball reaches the slate
};

/// A piece of motion with constant linear and angular acceleration, valid for `duration`
/// seconds from its start (then `ends_with` happens). Table frame, SI.
struct ClothMotion {
  Vec3 acc = Vec3::Zero();      ///< m/s²
  Vec3 ang_acc = Vec3::Zero();  ///< rad/s²
  double duration = 0.0;        ///< s; infinity when nothing ends it
  Transition ends_with = Transition::None;
};

/// The interface every cloth model implements.
class ClothModel {
 public:
  virtual ~ClothModel() = default;
  /// The motion of `ball` (on the slate or airborne) from now until its next transition.
  virtual ClothMotion motion(const Ball& ball) const = 0;
  /// Applies `t` to the ball at the moment it happens (snaps to exact rolling, to rest, ...),
  /// updating its state. Returns the event it corresponds to, if any is reported.
  virtual void apply(Transition t, Ball& ball) const = 0;
  /// Classifies a ball on the slate after an impulse: sliding, rolling, spinning or stationary.
  virtual MotionState classify(const Ball& ball) const = 0;
};

/// Leckie & Greenspan (2005), docs/PHYSICS.md: while the contact point slips, only sliding
/// friction u_s·m·g against the slip; once rolling, v and ω·R fall together at u_r·g; spin about
/// the vertical decays at spin_decel; airborne balls feel gravity only.
std::unique_ptr<ClothModel> makeClothLeckieGreenspan(const table::PhysicsParams& params);

}  // namespace pool::physics
