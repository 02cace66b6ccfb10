// The cue strike: yaw, tip offset, elevation and speed become the cue ball's velocity and spin
// (Alciatore TP ).
#pragma once

#include <string>

#include "core/result.h"
#include "physics/ball.h"
#include "physics/shot_limits.h"
#include "table/physics_params.h"

namespace pool::physics {

/// A shot as the player makes it. Angles in radians.
struct CueShot {
  double yaw = 0.0;       ///< heading of the cue in the table plane, 0 = +x, pi/2 = +y
  double tip_side = 0.0;  ///< a: cue line offset right of centre, fraction of R, seen from behind
  double tip_height =
      0.0;  ///< b: cue line offset above centre, fraction of R, perpendicular to the cue
  double elevation = 0.0;  ///< cue angle above horizontal, [0, kMaxElevation] (shot_limits.h)
  double speed = 0.0;      ///< m/s: the cue's speed, or the ball's if speed_is_ball
  bool speed_is_ball = false;
  int ball = kCueBall;  ///< the ball struck: the cue ball (three-cushion: the shooter's own)
};

/// The cue ball's motion just after the strike.
struct StrikeOutcome {
  Vec3 vel;             ///< m/s (points down into the slate when the cue is elevated)
  Vec3 ang_vel;         ///< rad/s
  double squirt = 0.0;  ///< angle of the ball's heading off the cue line, rad (+ = to the left)
};

/// Checks a shot's values with checkShotRange (physics/shot_limits.h): finite, speed and
/// elevation in range, offset within the table's miscue limit; any heading.
Check<ShotProblem> validateShot(const CueShot& shot, const table::PhysicsParams& params);

/// The strike model: point impulse along the cue (mass cue_mass) through the contact point of
/// the offset line; the heading then turns by the squirt angle (cue_end_mass) in cue mode.
Result<StrikeOutcome> strikeCueBall(const CueShot& shot, const table::PhysicsParams& params);

}  // namespace pool::physics
