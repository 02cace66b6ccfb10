// Cue strike: a frictionless point impulse along the cue (Alciatore TP A-30), squirt per TP A-31.
#include "physics/cue_strike.h"

#include <cmath>
#include <limits>

#include "physics/shot_limits.h"

namespace pool::physics {

namespace {

/// Unit vectors of the cue: d along the cue (toward the ball, tilted down by the elevation),
/// right (horizontal, right of the cue seen from behind) and up (perpendicular to both).
struct CueFrame {
  Vec3 d, right, up;
};

CueFrame cueFrame(double yaw, double elevation) {
  CueFrame f;
  f.d = Vec3(std::cos(elevation) * std::cos(yaw), std::cos(elevation) * std::sin(yaw),
             -std::sin(elevation));
  f.right = Vec3(std::sin(yaw), -std::cos(yaw), 0.0);
  f.up = f.right.cross(f.d);
  return f;
}

}  // namespace

Check<ShotProblem> validateShot(const CueShot& shot, const table::PhysicsParams& params) {
  ShotRanges ranges;
  ranges.miscue_limit = params.miscue_limit;
  // The heading is an angle like any other here: a turn more or less strikes the same way.
  ranges.max_abs_yaw = std::numeric_limits<double>::infinity();
  return checkShotRange({shot.speed, shot.elevation, shot.tip_side, shot.tip_height, shot.yaw},
                        ranges);
}

Result<StrikeOutcome> strikeCueBall(const CueShot& shot, const table::PhysicsParams& params) {
  if (auto ok = validateShot(shot, params); !ok) return Result<StrikeOutcome>::fail(ok.error());
  const double m = params.ball_mass;
  const double R = params.ball_radius;
  const double a = shot.tip_side;
  const double b = shot.tip_height;
  const double off2 = std::min(1.0, a * a + b * b);
  const CueFrame f = cueFrame(shot.yaw, shot.elevation);

  // Where the cue's line first meets the sphere, relative to the centre.
  const Vec3 r = R * (a * f.right + b * f.up - std::sqrt(1.0 - off2) * f.d);

  // Impulse along the cue: J = 2 m V0 / (1 + m/M + 2.5 (a² + b²)); in "ball" mode scaled so
  // the ball leaves at the requested speed.
  const double J = shot.speed_is_ball
                       ? m * shot.speed
                       : 2.0 * m * shot.speed / (1.0 + m / params.cue_mass + 2.5 * off2);
  const double inertia = 0.4 * m * R * R;

  StrikeOutcome out;
  out.vel = (J / m) * f.d;
  out.ang_vel = r.cross(J * f.d) / inertia;

  // Squirt turns the heading away from the side struck (right English → left), cue mode only.
  if (!shot.speed_is_ball) {
    const double mr = m / params.cue_end_mass;
    out.squirt = std::atan(2.5 * a * std::sqrt(std::max(0.0, 1.0 - a * a)) /
                           (1.0 + mr + 2.5 * (1.0 - a * a)));
    const Eigen::AngleAxisd turn(out.squirt, Vec3::UnitZ());
    out.vel = turn * out.vel;
  }
  return Result<StrikeOutcome>::ok(out);
}

}  // namespace pool::physics
